// Folding of atoms that the hard clauses force, after grounding (both the generic
// grounder and the generated grounding code end with it).
//
// A free atom outside every exactly-one block with a hard unit clause (x) or (!x) has
// that value in every feasible state; so has one whose hard clause became unit once
// other forced atoms were fixed (unit propagation to a fixpoint). Such atoms are
// removed from the network and recorded as fixed in the query index, exactly like
// atoms fixed by evidence: clauses they satisfy are dropped (a soft one adds its
// weight to the network constant), literals they falsify are removed. The distribution
// over the remaining atoms and log Z are unchanged.
//
// Example (indoor rule base): `!Adj(a, b) => !SaLe(a, b)` fixes SaLe(a, b) false for
// every non-adjacent pair, most of the network's atoms on a floor plan.
//
// When propagation meets a contradiction (a hard clause all of whose literals are
// forced false), the network is left as it was: inference then reports the
// unsatisfiable constraints as it always did.
#pragma once

#include <cstdint>

#include "runtime/mln/grounder.h"

namespace ksmc::runtime::mln {

// Returns the number of atoms folded.
std::int32_t fold_forced_atoms(Grounding& grounding);

}  // namespace ksmc::runtime::mln
