// What report.html shows, read from a run's output folder (the stable output files of the
// domains, see docs/report.md):
//   {"kind": "indoor" | "tabletop" | "segments" | "run",   chosen by the files present
//    "folder": "<folder name>", "summary": {...summary.json...},
//    "world": world.json, "scene_graph": scene_graph.json, "segments": segments.json,
//    "scene_input": {"camera", "table", "objects": [{"id", "model", "size"}]}  (table-top:
//                   the input scene named in summary.json, when it can still be read),
//    "trace": trace_columns(trace.csv), "images": {"overlay": "data:image/png;base64,..."}}
// Absent files are absent keys.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

namespace ksmc::runtime::report {

struct FolderLimits {
  std::size_t max_image_bytes = 6u << 20U;  // overlay.png larger than this is not embedded
  std::size_t max_trace_rows = 2000;        // per chain
};

// `summary` is the run summary (summary.json's content; domain_main passes it before the
// file is written). Throws std::runtime_error naming the file when one is malformed.
nlohmann::json collect_run_data(const std::filesystem::path& dir, const nlohmann::json& summary,
                                const FolderLimits& limits = {});

}  // namespace ksmc::runtime::report
