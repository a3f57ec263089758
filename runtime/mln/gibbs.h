// Block-aware Gibbs sampling on the ground network.
//
// A free atom is resampled from its full conditional; an exactly-one block is
// resampled as one categorical variable over its atoms. Hard clauses have zero
// probability: the chain starts from a state satisfying them (found by WalkSAT) and a
// value violating one is never chosen. Atoms tied by hard equivalences (pairs of hard
// clauses a v b, !a v !b, e.g. from SaLe(a,b) => SaLe(b,a) both ways) are flipped
// together, which single-site Gibbs could never do. Marginals are Rao-Blackwellised (the average
// of the conditional probabilities computed at each update), which has lower variance
// than counting. Deterministic for a seed.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "runtime/mln/ground_network.h"
#include "runtime/mln/inference_result.h"

namespace ksmc::runtime::mln {

using SampleObserver = std::function<void(std::span<const std::uint8_t> state)>;

struct GibbsOptions {
  std::int64_t burn_in = 100;   // sweeps discarded
  std::int64_t samples = 1000;  // sweeps recorded
  std::uint64_t seed = 1;
  bool rao_blackwell = true;    // false: plain counts of sampled values
  SampleObserver on_sample;     // called with the state after each recorded sweep
};

InferenceResult gibbs_sampling(const GroundNetwork& net, const GibbsOptions& options = {});

}  // namespace ksmc::runtime::mln
