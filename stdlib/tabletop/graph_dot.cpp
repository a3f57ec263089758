#include "stdlib/tabletop/graph_dot.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"

extern char** environ;

namespace ksmc::stdlib::tabletop {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

std::string quote(const std::string& s) { return "\"" + escape(s) + "\""; }

std::filesystem::path find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    const auto candidate = std::filesystem::path(dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

}  // namespace

std::string graph_dot(const TabletopResult& r) {
  validate_result(r);
  std::string out = "digraph scene_graph {\n  rankdir=BT;\n  node [shape=box, style=filled, fontname=\"Helvetica\"];\n";
  out += fmt::format("  {} [fillcolor=\"#bbbbbb\"];\n", quote(kTableId));
  for (std::size_t i = 0; i < r.scene.objects.size(); ++i) {
    const auto& o = r.scene.objects[i];
    if (r.probabilities.empty()) {  // no decisions output: relations only
      out += fmt::format("  {} [fillcolor=\"#99dd99\"];\n", quote(o.id));
      continue;
    }
    const auto& p = r.probabilities[i];
    const auto f = decide(p.false_prob);
    const auto h = decide(p.hidden_prob);
    const char* fill = (f && *f) ? "#ff6666" : (h && *h) ? "#66ffff" : "#99dd99";
    out += fmt::format("  {} [label={}, fillcolor=\"{}\"];\n", quote(o.id),
                       "\"" + escape(o.id) + fmt::format("\\nfalse {:.3f}  hidden {:.3f}\"", p.false_prob, p.hidden_prob), fill);
  }
  for (const auto& [upper, lower] : support_edges(r.evidence))
    out += fmt::format("  {} -> {};\n", quote(lower), quote(upper));
  for (const auto& [a, b] : unstable_contact_edges(r.evidence))
    out += fmt::format("  {} -> {} [dir=none, style=dashed, constraint=false];\n", quote(a), quote(b));
  out += "}\n";
  return out;
}

std::string render_dot_png(const std::filesystem::path& dot_file, const std::filesystem::path& png_file,
                           const std::string& dot_executable) {
  const std::filesystem::path exe = dot_executable.empty() ? find_on_path("dot") : std::filesystem::path(dot_executable);
  if (exe.empty() || ::access(exe.c_str(), X_OK) != 0)
    return fmt::format("Graphviz 'dot' not found{}; skipping {}",
                       dot_executable.empty() ? " on PATH" : " at " + dot_executable, png_file.string());
  const std::filesystem::path tmp = png_file.string() + ".dot-render.tmp";
  std::vector<std::string> args = {exe.string(), "-Tpng", dot_file.string(), "-o", tmp.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    return fmt::format("cannot start {}; skipping {}", exe.string(), png_file.string());
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    return fmt::format("{} -Tpng failed on {}; skipping {}", exe.string(), dot_file.string(), png_file.string());
  }
  std::ifstream in(tmp, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  std::error_code ec;
  std::filesystem::remove(tmp, ec);
  ksmc::runtime::io::write_file_atomic(png_file, bytes);
  return {};
}

}  // namespace ksmc::stdlib::tabletop
