// Writes a table-top result folder, every file atomically:
//   scene_graph.json, graph.dot, graph.png (Graphviz dot; skipped with a warning when
//   dot is absent), overlay.png.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stdlib/tabletop/result.h"

namespace ksmc::stdlib::tabletop {

struct ResultWriterOptions {
  std::string dot_executable;  // empty: "dot" on PATH
  bool render_graph_png = true;
  bool render_overlay = true;
};

struct ResultWriteReport {
  std::vector<std::filesystem::path> written;
  std::vector<std::string> warnings;
};

ResultWriteReport write_results(const TabletopResult& result, const std::filesystem::path& out_dir,
                                const ResultWriterOptions& options = {});

}  // namespace ksmc::stdlib::tabletop
