#include "runtime/mln/components.h"

#include <numeric>

namespace ksmc::runtime::mln {
namespace {

struct UnionFind {
  std::vector<std::int32_t> parent;
  explicit UnionFind(std::int32_t n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  std::int32_t find(std::int32_t x) {
    while (parent[x] != x) {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  }
  void unite(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) parent[b] = a; else parent[a] = b;  // root = smallest id
  }
};

}  // namespace

std::vector<Component> split_components(const GroundNetwork& net) {
  const std::int32_t n = net.num_atoms();
  UnionFind uf(n);
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    const auto lits = net.clause(c);
    for (std::size_t i = 1; i < lits.size(); ++i) uf.unite(lit_atom(lits[0]), lit_atom(lits[i]));
  }
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) {
    const auto atoms = net.block(b);
    for (std::size_t i = 1; i < atoms.size(); ++i) uf.unite(atoms[0], atoms[i]);
  }
  std::vector<std::int32_t> comp_of_root(static_cast<std::size_t>(n), -1);
  std::vector<Component> comps;
  for (AtomId a = 0; a < n; ++a) {
    const std::int32_t r = uf.find(a);
    if (comp_of_root[r] < 0) {
      comp_of_root[r] = static_cast<std::int32_t>(comps.size());
      comps.emplace_back();
    }
    comps[comp_of_root[r]].atoms.push_back(a);
  }
  for (std::int32_t c = 0; c < net.num_clauses(); ++c)
    comps[comp_of_root[uf.find(lit_atom(net.clause(c)[0]))]].clauses.push_back(c);
  for (std::int32_t b = 0; b < net.num_blocks(); ++b)
    comps[comp_of_root[uf.find(net.block(b)[0])]].blocks.push_back(b);
  return comps;
}

GroundNetwork extract_component(const GroundNetwork& net, const Component& comp) {
  GroundNetwork sub;
  sub.set_label_names(net.label_names());
  sub.set_origin_names(net.origin_names());
  std::vector<AtomId> local(static_cast<std::size_t>(net.num_atoms()), -1);
  for (std::size_t i = 0; i < comp.atoms.size(); ++i) {
    local[comp.atoms[i]] = static_cast<AtomId>(i);
    sub.add_atom(net.label(comp.atoms[i]));
  }
  std::vector<Lit> lits;
  for (std::int32_t c : comp.clauses) {
    lits.clear();
    for (Lit l : net.clause(c)) lits.push_back(make_lit(local[lit_atom(l)], lit_negated(l)));
    if (net.is_hard(c)) sub.add_hard_clause(lits, net.origin(c));
    else sub.add_clause(lits, net.weight(c), net.origin(c));
  }
  std::vector<AtomId> atoms;
  for (std::int32_t b : comp.blocks) {
    atoms.clear();
    for (AtomId a : net.block(b)) atoms.push_back(local[a]);
    sub.add_exactly_one(atoms);
  }
  return sub;
}

}  // namespace ksmc::runtime::mln
