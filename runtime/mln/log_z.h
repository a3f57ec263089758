// The log partition function of a ground network given its evidence (the quantity
// `prior mln` needs: log sum over query states of exp(sum of satisfied weights),
// including the constant of folded evidence clauses).
//
// Exact per connected component when the component is small enough; otherwise an
// annealed importance sampling (AIS, Neal 2001) estimate for that component:
//   f_0(x) = 1 on states respecting the blocks (Z_0 = 2^atoms * prod block sizes),
//   f_t(x) = exp(-beta_t * soft_cost(x) - beta_t * H * hard_violations(x)), beta 0 -> 1,
//   final weight times [x satisfies every hard clause],
// with one block-aware Gibbs sweep per temperature and `chains` independent chains.
// The estimate of Z is unbiased; its log has a small downward bias; the standard
// error (delta method) is reported.
#pragma once

#include <cstdint>

#include "runtime/mln/exact.h"
#include "runtime/mln/ground_network.h"

namespace ksmc::runtime::mln {

struct LogZOptions {
  ExactOptions exact;
  std::int32_t chains = 64;
  std::int32_t temperatures = 400;
  double hard_penalty = 20.0;  // H: log-weight per violated hard clause at beta = 1
  std::uint64_t seed = 1;
  bool force_ais = false;      // estimate every component (for testing the estimator)
};

struct LogZResult {
  double log_z = 0.0;
  bool exact = true;           // false when any component was estimated
  double std_error = 0.0;      // of log_z (0 when exact)
  std::int32_t estimated_components = 0;
};

LogZResult log_partition(const GroundNetwork& net, const LogZOptions& options = {});

// AIS estimate of log Z of one network (without its constant): {log_z, std_error}.
// Throws MlnError if no chain ends in a state satisfying the hard clauses.
std::pair<double, double> ais_log_z(const GroundNetwork& net, const LogZOptions& options, std::uint64_t seed);

}  // namespace ksmc::runtime::mln
