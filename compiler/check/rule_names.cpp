#include "compiler/check/rule_names.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <vector>

#include "compiler/fmt/printer.h"

namespace ksmc::compiler::check {
namespace {

void predicates_of(const ast::Formula& f, std::vector<std::string>& out) {
  if (f.kind == ast::Formula::Kind::Atom) {
    if (std::find(out.begin(), out.end(), f.atom.pred.name) == out.end()) out.push_back(f.atom.pred.name);
    return;
  }
  for (const auto& c : f.children) predicates_of(c, out);
}

std::string identifier_part(const std::string& s) {
  std::string out;
  for (unsigned char ch : s) {
    if (std::isalnum(ch)) out.push_back(static_cast<char>(std::tolower(ch)));
    else if (!out.empty() && out.back() != '_') out.push_back('_');
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace

std::string normalized_rule_text(const ast::Rule& r) {
  if (!r.exactly_one) return fmt::print_formula(r.formula);
  std::string s = "exactly one of ";
  for (std::size_t i = 0; i < r.alternatives.size(); ++i) s += (i ? ", " : "") + fmt::print_atom(r.alternatives[i]);
  return s;
}

std::uint32_t fnv1a(std::string_view text) {
  std::uint32_t h = 2166136261u;
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 16777619u;
  }
  return h;
}

std::string rule_name(const ast::Rule& r, bool long_hash) {
  if (r.label) return r.label->name;
  std::vector<std::string> preds;
  if (r.exactly_one) {
    for (const auto& a : r.alternatives)
      if (std::find(preds.begin(), preds.end(), a.pred.name) == preds.end()) preds.push_back(a.pred.name);
  } else if (r.formula.kind == ast::Formula::Kind::Implies || r.formula.kind == ast::Formula::Kind::Iff) {
    predicates_of(r.formula.children.at(1), preds);
  } else {
    predicates_of(r.formula, preds);
  }
  std::string name;
  for (std::size_t i = 0; i < preds.size() && i < 3; ++i) {
    const std::string part = identifier_part(preds[i]);
    if (!part.empty()) name += (name.empty() ? "" : "_") + part;
  }
  if (name.empty()) name = "rule";
  const std::uint32_t h = fnv1a(normalized_rule_text(r));
  char hex[12];
  if (long_hash) std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(h));
  else std::snprintf(hex, sizeof hex, "%04x", static_cast<unsigned>((h ^ (h >> 16)) & 0xffffu));
  return name + "_" + hex;
}

}  // namespace ksmc::compiler::check
