#include "runtime/mln/forced_atoms.h"

#include <utility>
#include <vector>

namespace ksmc::runtime::mln {
namespace {

constexpr std::int8_t kFree = -1;

// The literal a hard clause forces under `value`: -1 when it is satisfied or has two or
// more open literals, -2 when every literal is false (a contradiction).
Lit forced_literal(const GroundNetwork& net, std::int32_t c, const std::vector<std::int8_t>& value) {
  Lit open = -1;
  std::int32_t open_count = 0;
  for (Lit l : net.clause(c)) {
    const std::int8_t v = value[lit_atom(l)];
    if (v == kFree) {
      if (++open_count > 1) return -1;
      open = l;
    } else if ((v == 1) != lit_negated(l)) {
      return -1;
    }
  }
  return open_count == 0 ? -2 : open;
}

// Unit propagation over the hard clauses; false on a contradiction. A few passes over
// all hard clauses settle the usual networks (indoor: one pass fixes every non-adjacent
// SaLe, the second finds nothing new) without building occurrence lists; a longer chain
// of implications continues with a queue over the atoms' hard clauses, so the cost stays
// linear in the clauses' size.
bool propagate(const GroundNetwork& net, std::vector<std::int8_t>& value) {
  std::vector<AtomId> fixed;
  auto fix = [&](Lit l) {
    if (net.block_of(lit_atom(l)) >= 0) return false;  // blocks are constraints of their own
    value[lit_atom(l)] = lit_negated(l) ? 0 : 1;
    fixed.push_back(lit_atom(l));
    return true;
  };
  constexpr int kPasses = 3;
  bool changed = true;
  for (int pass = 0; pass < kPasses && changed; ++pass) {
    changed = false;
    for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
      if (!net.is_hard(c) || (pass == 0 && net.clause(c).size() != 1)) continue;
      const Lit l = forced_literal(net, c, value);
      if (l == -2) return false;
      if (l >= 0) changed = fix(l) || changed;
    }
  }
  if (!changed) return true;
  const Occurrences occ = build_occurrences(net);
  for (std::size_t head = 0; head < fixed.size(); ++head) {  // every fixed atom, again: idempotent
    const AtomId a = fixed[head];
    for (std::int32_t k = occ.offsets[a]; k < occ.offsets[a + 1]; ++k) {
      const std::int32_t c = occ.clause[k];
      if (!net.is_hard(c) || (value[a] == 1) != (occ.negated[k] != 0)) continue;  // not made false by a
      const Lit l = forced_literal(net, c, value);
      if (l == -2) return false;
      if (l >= 0) fix(l);
    }
  }
  return true;
}

}  // namespace

std::int32_t fold_forced_atoms(Grounding& grounding) {
  const GroundNetwork& net = grounding.network;
  const std::int32_t n = net.num_atoms();
  std::vector<std::int8_t> value(static_cast<std::size_t>(n), kFree);
  if (!propagate(net, value)) return 0;
  bool any = false;
  for (AtomId a = 0; a < n && !any; ++a) any = value[a] != kFree;
  if (!any) return 0;

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
