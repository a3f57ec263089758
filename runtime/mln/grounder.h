// Generic (interpreted) grounding of a Program over run-time constants and evidence.
//
// Evidence predicates are closed world (atoms not given true are false); query atoms
// are free unless given. Evidence is folded while grounding: clauses satisfied by
// evidence are dropped (a soft one adds its weight to the network constant), false
// literals are removed, and a hard clause left empty is an MlnError naming the rule,
// its text, location and the binding. Exactly-one groups and `p(x, t!)` become
// network blocks after folding their evidence.
//
// Query atoms are indexed densely: index = offset(predicate) + mixed radix of the
// argument constant indices. Each query atom maps to a free network atom or to a
// fixed value (when evidence or a block fixed it).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/mln/evidence.h"
#include "runtime/mln/ground_network.h"
#include "runtime/mln/inference_result.h"
#include "runtime/mln/program.h"

namespace ksmc::runtime::mln {

struct QueryIndex {
  std::vector<std::int64_t> offset;  // per predicate; -1 for evidence predicates
  std::int64_t num_query_atoms = 0;
  std::vector<AtomId> atom;          // per query atom: network atom, or -1 when fixed
  std::vector<std::int8_t> fixed;    // value when atom == -1
  std::vector<std::int64_t> query_of_atom;  // network atom -> query atom index
};

struct Grounding {
  GroundNetwork network;
  QueryIndex index;

  // Dense query index of p(args) (args = constant indices); p must be a query predicate.
  std::int64_t query_index(std::int32_t predicate, std::span<const std::int32_t> args) const;
  // P(query atom = true) from an engine's result (0/1 for fixed atoms).
  double marginal(const InferenceResult& result, std::int64_t query_index) const;
  double marginal(const InferenceResult& result, std::int32_t predicate, std::span<const std::int32_t> args) const {
    return marginal(result, query_index(predicate, args));
  }
  // "supported(A)" for a query index.
  std::string atom_name(std::int64_t query_index) const;

  // Filled by ground(); needed by the helpers above.
  const Program* program = nullptr;
  const Domain* domain = nullptr;
  std::vector<std::vector<std::int32_t>> radix;  // per predicate
};

// Throws MlnError on an invalid program, an unsatisfiable hard rule or a violated
// exactly-one group. `program` and `domain` must outlive the result.
Grounding ground(const Program& program, const Domain& domain, const Evidence& evidence);

// The part of ground() that does not depend on the clauses: query index, exactly-one
// blocks (folded against the evidence) and free atoms. Generated grounding code
// (compiler/emit) starts here and adds the clauses itself through FactorContext.
Grounding prepare_grounding(const Program& program, const Domain& domain, const Evidence& evidence);

}  // namespace ksmc::runtime::mln
