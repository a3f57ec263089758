#include "stdlib/indoor/io/scene_dot.h"

#include <algorithm>
#include <iterator>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
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

// Fill colours per type, by the type's place in WorldResult::types (the seed's figures: the
// first types yellow, green, blue, grey); white for an untyped unit.
const char* fill_of(const WorldResult& w, const std::string& type) {
  static const char* const fills[] = {"#fff2cc", "#d9ead3", "#cfe2f3", "#eeeeee", "#f4cccc", "#d9d2e9", "#fce5cd", "#d0e0e3"};
  const auto it = std::find(w.types.begin(), w.types.end(), type);
  if (type.empty() || it == w.types.end()) return "#ffffff";
  return fills[static_cast<std::size_t>(it - w.types.begin()) % std::size(fills)];
}

}  // namespace

std::string scene_dot_text(const WorldResult& w) {
  validate_world(w, false);
  std::string out = "graph scene {\n";
  out += "  graph [overlap=false, splines=true];\n";
  out += "  node [shape=box, style=\"rounded,filled\", fontname=\"Helvetica\"];\n";
  out += "  edge [fontname=\"Helvetica\", fontsize=10];\n";
  for (const auto& u : w.units) {
    double p = 0.0;
    if (const auto it = u.type_probs.find(u.type); it != u.type_probs.end()) p = it->second;
    const std::string label = u.type_probs.empty()
                                  ? fmt::format("{}\\n{}", u.id, escape(u.type))
                                  : fmt::format("{}\\n{} ({:.2f})", u.id, escape(u.type), p);
    out += fmt::format("  {} [label=\"{}\", fillcolor=\"{}\"];\n", node(u.id), label, fill_of(w, u.type));
  }
  bool outside = false;
  for (const auto& d : w.doors) outside = outside || d.unit_a == 0 || d.unit_b == 0;
  if (outside) out += "  outside [shape=plaintext, style=\"\", label=\"outside\"];\n";
  for (const auto& [a, b] : w.adjacent) {
    out += fmt::format("  {} -- {} [color=\"grey50\", style=dashed];\n", node(a), node(b));
  }
  for (const auto& d : w.doors) {
    out += fmt::format("  {} -- {} [style=bold, penwidth=2.5, color=\"#00a0a0\", label=\"d{}\"];\n",
                       node(d.unit_a), node(d.unit_b), d.id);
  }
  out += "}\n";
  return out;
}

void write_scene_dot(const std::filesystem::path& path, const WorldResult& w) {
  runtime::io::write_file_atomic(path, scene_dot_text(w));
}

}  // namespace ksmc::stdlib::indoor::io
