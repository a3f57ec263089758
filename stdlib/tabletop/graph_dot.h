// Graphviz view of the table-top scene graph: one box per object (false estimates
// red, objects resting on a hidden object cyan, undecided ones yellow), arrows from the
// supporting to the supported object (seed Fig. 4.17–4.23), undirected dashed lines for
// unstable contact, red dotted lines labelled "cuts" between boxes that cut each other.
#pragma once

#include <filesystem>
#include <string>

#include "stdlib/tabletop/result.h"

namespace ksmc::stdlib::tabletop {

std::string graph_dot(const TabletopResult& result);

// Renders `dot_file` to `png_file` with `dot -Tpng` (written atomically). Returns an
// empty string on success, otherwise the reason it was skipped (e.g. dot not found).
// `dot_executable` empty: look for "dot" on PATH.
std::string render_dot_png(const std::filesystem::path& dot_file, const std::filesystem::path& png_file,
                           const std::string& dot_executable = "");

}  // namespace ksmc::stdlib::tabletop
