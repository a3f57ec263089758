// `ksmc learn FILE.ksm --data a.db b.db ...`: learns the soft rule weights of FILE from
// fully observed training worlds (each .db: the evidence atoms and the query atoms that
// are true; query atoms not listed are false) and writes FILE again with the learned
// weights in place of the old ones: only the weight tokens change, layout and comments
// stay (a `prob p:` rule gets the probability of its learned log-odds).
// Generative pseudo-log-likelihood by default; `--method cll` maximises the conditional
// likelihood with its exact gradient (observed minus expected clause counts under exact
// inference; runtime/mln/weight_learning.h) where exact inference applies to every training
// network, and from MC-SAT expectations otherwise (`--expectations sampled` forces them,
// `--expectations exact` refuses the fallback); stderr says which path ran. `--per-formula` (cll only) learns one weight
// per formula under per-formula semantics (compiler/lower/per_formula.h).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "compiler/lower/mln_ir.h"

namespace ksmc::compiler::learn {

struct LearnRequest {
  std::string method = "pll";      // pll | cll
  double prior_sigma = 10.0;       // --l2 SIGMA: standard deviation of the Gaussian prior
  std::string out_path;            // --out FILE (stdout when empty)
  bool per_formula = false;        // --per-formula: `ir` was rewritten by use_per_formula_weights (cll only)
  std::string expectations = "auto";  // --expectations auto|exact|sampled (cll only)
  std::int64_t samples = -1;       // --samples N: MC-SAT samples per sampled gradient (< 0: the default)
  std::uint64_t seed = 1;          // --seed N: MC-SAT seed of the sampled path
};

// Returns 0, 1 on bad data (every bad .db line reported) or unlearnable input, 2 on usage.
int run_learn(const lower::MlnIr& ir, const std::string& ksm_path, const std::vector<std::string>& data,
              const LearnRequest& request, std::ostream& out, std::ostream& err);

// The source text with each (line, spelling) weight token of `rules` replaced: the first
// `w <spelling>` / `prob <spelling>` at or after the start of the rule's line. Exposed for
// tests. `replacement[i]` empty: rule i unchanged.
std::string replace_weights(const std::string& source, const std::vector<lower::RuleIr>& rules,
                            const std::vector<std::string>& replacement);

}  // namespace ksmc::compiler::learn
