// MC-SAT (Poon & Domingos 2006): slice sampling over the ground network.
//
// Each step keeps every hard clause and, with probability 1 - exp(-|w|), every soft
// clause the current state gets right (a satisfied w > 0 clause, or an unsatisfied
// w < 0 clause, which then must stay all-false), and draws the next state nearly
// uniformly from the states satisfying that set with SampleSAT (simulated annealing
// moves mixed with WalkSAT moves, starting from the current state; blocks are moved
// as one variable). If SampleSAT ends outside the set the chain stays put, so no
// sample ever violates a hard clause. Deterministic for a seed.
#pragma once

#include <cstdint>

#include "runtime/mln/gibbs.h"
#include "runtime/mln/ground_network.h"
#include "runtime/mln/inference_result.h"

namespace ksmc::runtime::mln {

struct McSatOptions {
  std::int64_t burn_in = 50;
  std::int64_t samples = 1000;
  std::uint64_t seed = 1;
  std::int32_t sample_sat_steps = 0;  // SA/WalkSAT moves per sample; 0 = 4 x variables (>= 20)
  double sa_probability = 0.5;        // share of simulated-annealing moves
  double temperature = 0.5;           // SA temperature (in units of clauses)
  double walk_noise = 0.3;
  SampleObserver on_sample;
};

InferenceResult mc_sat(const GroundNetwork& net, const McSatOptions& options = {});

}  // namespace ksmc::runtime::mln
