#include "compiler/lower/dump_ir.h"

#include <charconv>
#include <cmath>
#include <string>

namespace ksmc::compiler::lower {

namespace mln = ksmc::runtime::mln;

std::string format_weight(double w) {
  if (std::isinf(w)) return w > 0 ? "inf" : "-inf";
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, w);
  return std::string(buf, res.ptr);
}

std::string one_line(std::string_view text) {
  std::string out;
  bool space = false;
  for (char ch : text) {
    if (ch == '\n' || ch == '\r' || ch == '\t' || ch == ' ') {
      space = !out.empty();
      continue;
    }
    if (space) out.push_back(' ');
    space = false;
    out.push_back(ch);
  }
  return out;
}

std::string clause_text(const mln::Program& program, const mln::Clause& c) {
  std::string out;
  for (std::size_t i = 0; i < c.literals.size(); ++i) {
    const auto& l = c.literals[i];
    if (i) out += " v ";
    if (l.negated) out += "!";
    out += program.predicates[static_cast<std::size_t>(l.predicate)].name + "(";
    for (std::size_t a = 0; a < l.args.size(); ++a) {
      if (a) out += ", ";
      out += l.args[a].is_variable ? c.variables[static_cast<std::size_t>(l.args[a].variable)].name : l.args[a].constant;
    }
    out += ")";
  }
  return out;
}

void dump_ir(const MlnIr& ir, std::ostream& out) {
  const auto& p = ir.program;
  out << "domain " << ir.domain << "\n";
  for (std::size_t t = 0; t < p.types.size(); ++t) {
    out << "type " << p.types[t];
    if (t < ir.enumerated.size() && !ir.enumerated[t].empty()) {
      out << " = {";
      for (std::size_t k = 0; k < ir.enumerated[t].size(); ++k) out << (k ? ", " : "") << ir.enumerated[t][k];
      out << "}";
    }
    out << "\n";
  }
  for (const auto& pred : p.predicates) {
    out << (pred.query ? "query " : "evidence ") << pred.name << "(";
    for (std::size_t a = 0; a < pred.arg_types.size(); ++a) {
      out << (a ? ", " : "") << p.types[static_cast<std::size_t>(pred.arg_types[a])];
      if (static_cast<std::int32_t>(a) == pred.exclusive_arg) out << "!";
    }
    out << ")\n";
  }
  for (const auto& r : ir.rules) {
    out << "rule " << r.name << " " << r.file << ":" << r.line << " `" << r.text << "`\n";
    if (r.group >= 0) {
      const auto& g = p.groups[static_cast<std::size_t>(r.group)];
      out << "  exactly-one";
      for (std::size_t k = 0; k < g.predicates.size(); ++k)
        out << (k ? ", " : " ") << p.predicates[static_cast<std::size_t>(g.predicates[k])].name;
      out << "\n";
      continue;
    }
    for (int ci : r.clauses) {
      const auto& c = p.clauses[static_cast<std::size_t>(ci)];
      out << "  clause " << c.name << " " << (c.hard ? std::string("hard") : "w=" + format_weight(c.weight)) << ": ";
      bool any_exists = false;
      for (const auto& v : c.variables) any_exists = any_exists || v.existential;
      if (any_exists) {
        out << "exists";
        bool first = true;
        for (const auto& v : c.variables)
          if (v.existential) {
            out << (first ? " " : ", ") << v.name;
            first = false;
          }
        out << ": ";
      }
      out << clause_text(p, c) << "\n";
    }
  }
}

}  // namespace ksmc::compiler::lower
