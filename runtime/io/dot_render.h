// Renders a Graphviz file to PNG with the `dot` program, for the domains' graph.png outputs.
#pragma once

#include <filesystem>
#include <string>

namespace ksmc::runtime::io {

// Renders `dot_file` to `png_file` with `dot -Tpng` (written atomically). Returns an empty
// string on success, otherwise the reason it was skipped (e.g. dot not found, dot failed);
// nothing is written then. The reason names the PNG by its file name (outputs are often staged). `dot_executable` empty: look for "dot" on PATH.
std::string render_dot_png(const std::filesystem::path& dot_file, const std::filesystem::path& png_file,
                           const std::string& dot_executable = "");

}  // namespace ksmc::runtime::io
