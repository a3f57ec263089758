// What every inference engine returns: one marginal per free atom of the network,
// plus (when the engine computes one) the log partition function of the network,
// which includes the network's constant (the folded evidence).
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace ksmc::runtime::mln {

struct InferenceResult {
  std::vector<double> marginals;  // P(atom = true), index = network atom id
  double log_z = std::numeric_limits<double>::quiet_NaN();
  bool log_z_exact = false;       // false: estimate (or NaN if not computed)
  std::string method;             // "gibbs", "mcsat", "exact:enum 3, elim 1 (width 4)", "auto:enum 2, mcsat 1"
  std::int64_t samples = 0;       // samples behind the marginals (0 for exact)
};

}  // namespace ksmc::runtime::mln
