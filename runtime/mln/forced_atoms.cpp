#include "runtime/mln/forced_atoms.h"

#include <utility>
#include <vector>

namespace ksmc::runtime::mln {
namespace {

constexpr std::int8_t kFree = -1;

// Unit propagation over the hard clauses; false on a contradiction.
bool propagate(const GroundNetwork& net, std::vector<std::int8_t>& value) {
  bool changed = true;
  while (changed) {
    changed = false;
    for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
      if (!net.is_hard(c)) continue;
      Lit open = -1;
      std::int32_t open_count = 0;
      bool satisfied = false;
      for (Lit l : net.clause(c)) {
        const std::int8_t v = value[lit_atom(l)];
        if (v == kFree) {
          ++open_count;
          open = l;
        } else if ((v == 1) != lit_negated(l)) {
          satisfied = true;
          break;
        }
      }
      if (satisfied || open_count > 1) continue;
      if (open_count == 0) return false;
      if (net.block_of(lit_atom(open)) >= 0) continue;  // blocks are constraints of their own
      value[lit_atom(open)] = lit_negated(open) ? 0 : 1;
      changed = true;
    }
  }
  return true;
}

}  // namespace

std::int32_t fold_forced_atoms(Grounding& grounding) {
  const GroundNetwork& net = grounding.network;
  const std::int32_t n = net.num_atoms();
  std::vector<std::int8_t> value(static_cast<std::size_t>(n), kFree);
  bool any = false;
  for (std::int32_t c = 0; c < net.num_clauses() && !any; ++c)
    any = net.is_hard(c) && net.clause(c).size() == 1 && net.block_of(lit_atom(net.clause(c)[0])) < 0;
  if (!any || !propagate(net, value)) return 0;

  GroundNetwork out;
  out.set_label_names(net.label_names());
  out.set_origin_names(net.origin_names());
  out.add_constant(net.constant());
  QueryIndex& ix = grounding.index;
  std::vector<AtomId> local(static_cast<std::size_t>(n), -1);
  std::vector<std::int64_t> query_of_atom;
  std::int32_t folded = 0;
  for (AtomId a = 0; a < n; ++a) {
    const std::int64_t q = a < static_cast<AtomId>(ix.query_of_atom.size()) ? ix.query_of_atom[a] : -1;
    if (value[a] != kFree) {
      ++folded;
      if (q >= 0) {
        ix.atom[q] = -1;
        ix.fixed[q] = value[a];
      }
      continue;
    }
    local[a] = out.add_atom(net.label(a));
    query_of_atom.push_back(q);
    if (q >= 0) ix.atom[q] = local[a];
  }
  std::vector<Lit> lits;
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    lits.clear();
    bool satisfied = false;
    for (Lit l : net.clause(c)) {
      const std::int8_t v = value[lit_atom(l)];
      if (v == kFree) lits.push_back(make_lit(local[lit_atom(l)], lit_negated(l)));
      else if ((v == 1) != lit_negated(l)) satisfied = true;
    }
    if (net.is_hard(c)) {
      if (!satisfied) out.add_hard_clause(lits, net.origin(c));
    } else if (satisfied) {
      out.add_constant(net.weight(c));
    } else {
      out.add_clause(lits, net.weight(c), net.origin(c));  // an emptied one is dropped
    }
  }
  std::vector<AtomId> atoms;
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) {
    atoms.clear();
    for (AtomId a : net.block(b)) atoms.push_back(local[a]);
    out.add_exactly_one(atoms);
  }
  ix.query_of_atom = std::move(query_of_atom);
  grounding.network = std::move(out);
  return folded;
}

}  // namespace ksmc::runtime::mln
