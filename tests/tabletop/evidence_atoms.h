// The stdlib relation matrices (stdlib/tabletop/evidence.h) as the ground atoms of
// domains/tabletop.ksm's evidence predicates, for comparing against intended evidence. Test
// code: the stdlib names no predicate (a domain's evidence comes from its extractors).
#pragma once

#include <string>
#include <vector>

#include "stdlib/tabletop/evidence.h"

namespace ksmc::tests::tabletop {

struct GroundAtom {
  std::string predicate;
  std::vector<std::string> args;
  bool operator==(const GroundAtom&) const = default;
  auto operator<=>(const GroundAtom&) const = default;
};

// True atoms in a fixed order: table, stable, hover, contact, intersect, higher; bodies in
// index order within each predicate.
inline std::vector<GroundAtom> atoms(const ksmc::stdlib::tabletop::Evidence& ev) {
  std::vector<GroundAtom> out;
  const std::size_t n = ev.size();
  for (std::size_t i = 0; i < n; ++i)
    if (ev.is_table[i]) out.push_back({"table", {ev.ids[i]}});
  for (std::size_t i = 0; i < n; ++i)
    if (ev.stable[i]) out.push_back({"stable", {ev.ids[i]}});
  for (std::size_t i = 0; i < n; ++i)
    if (ev.hover[i]) out.push_back({"hover", {ev.ids[i]}});
  const std::pair<const char*, const std::vector<std::vector<char>>*> pairs[] = {
      {"contact", &ev.contact}, {"intersect", &ev.intersect}, {"higher", &ev.higher}};
  for (const auto& [name, m] : pairs)
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b)
        if (a != b && (*m)[a][b]) out.push_back({name, {ev.ids[a], ev.ids[b]}});
  return out;
}

}  // namespace ksmc::tests::tabletop
