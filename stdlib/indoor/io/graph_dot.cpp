#include "stdlib/indoor/io/graph_dot.h"

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/type_style.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

std::string node(int id) { return id == 0 ? std::string("outside") : fmt::format("u{}", id); }

}  // namespace

std::string graph_dot_text(const WorldResult& w) {
  validate_world(w, false);
  std::string out = "graph topology {\n";
  out += "  graph [overlap=false, splines=true];\n";
  out += "  node [shape=ellipse, style=filled, fontname=\"Helvetica\"];\n";
  out += "  edge [fontname=\"Helvetica\", fontsize=10];\n";
  for (const auto& u : w.units) {
    std::string tooltip = u.type.empty() ? "untyped" : u.type;
    if (const auto it = u.type_probs.find(u.type); it != u.type_probs.end()) tooltip += fmt::format(" {:.2f}", it->second);
    out += fmt::format("  {} [label=\"{}{}\", tooltip=\"{}\", fillcolor=\"{}\"];\n", node(u.id),
                       escape(type_letter(w.types, u.type)), u.id, escape(tooltip),
                       hex(lighten(type_colour(w.types, u.type), 0.35)));
  }
  bool outside = false;
  for (const auto& d : w.doors) outside = outside || d.unit_a == 0 || d.unit_b == 0;
  if (outside) out += "  outside [shape=plaintext, style=\"\", label=\"outside\"];\n";
  for (const auto& [a, b] : w.adjacent) out += fmt::format("  {} -- {} [style=dashed, color=\"grey50\"];\n", node(a), node(b));
  for (const auto& d : w.doors)
    out += fmt::format("  {} -- {} [style=solid, penwidth=2, label=\"d{}\"];\n", node(d.unit_a), node(d.unit_b), d.id);
  out += "}\n";
  return out;
}

void write_graph_dot(const std::filesystem::path& path, const WorldResult& w) {
  runtime::io::write_file_atomic(path, graph_dot_text(w));
}

}  // namespace ksmc::stdlib::indoor::io
