#include "stdlib/tabletop/graph_dot.h"

#include <fmt/format.h>

#include "runtime/io/dot_render.h"

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
    // red: false; cyan: hidden; yellow: undecided (P within 0.4-0.6) on either; green: neither.
    const char* fill = (f && *f) ? "#ff6666" : (h && *h) ? "#66ffff" : (!f || !h) ? "#ffee88" : "#99dd99";
    out += fmt::format("  {} [label={}, fillcolor=\"{}\"];\n", quote(o.id),
                       "\"" + escape(o.id) + fmt::format("\\nfalse {:.3f}  hidden {:.3f}\"", p.false_prob, p.hidden_prob), fill);
  }
  for (const auto& [upper, lower] : support_edges(r))
    out += fmt::format("  {} -> {};\n", quote(lower), quote(upper));
  for (const auto& [a, b] : unstable_contact_edges(r))
    out += fmt::format("  {} -> {} [dir=none, style=dashed, constraint=false];\n", quote(a), quote(b));
  for (const auto& [a, b] : intersect_edges(r.evidence))  // boxes that cut each other: one is wrong
    out += fmt::format("  {} -> {} [dir=none, style=dotted, color=\"#cc0000\", penwidth=2, label=\"cuts\", "
                       "fontcolor=\"#cc0000\", fontsize=10, constraint=false];\n",
                       quote(a), quote(b));
  out += "}\n";
  return out;
}

std::string render_dot_png(const std::filesystem::path& dot_file, const std::filesystem::path& png_file,
                           const std::string& dot_executable) {
  return runtime::io::render_dot_png(dot_file, png_file, dot_executable);
}

}  // namespace ksmc::stdlib::tabletop
