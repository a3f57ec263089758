// Weight learning from fully observed training worlds.
//
// Parameters are tied: each program clause c either has a learned parameter
// (weight(c) = params[param_of_clause[c]] * scale_of_clause[c], e.g. scale 1/k for the k
// CNF clauses of one formula) or keeps its weight (param -1, and every hard clause).
// A training set is one ground network (evidence folded, query atoms free; clause
// origins = program clause indices, as ground() and generated code set them) with the
// observed values of its free atoms in one or more worlds.
//
// Objectives (both concave; maximised with an L2 / Gaussian prior of mean 0 and standard
// deviation prior_sigma on each parameter):
//  * PseudoLikelihood (generative): sum over worlds and variables (a free atom, or an
//    exactly-one block as one variable) of log P(x_v | all other atoms), values that
//    break a hard clause excluded. The per-variable conditionals are tabulated once, so an
//    iteration costs one pass over the tables.
//  * ConditionalLikelihood (discriminative): sum over worlds of log P(x | evidence)
//    = sum_c w_c n_c(x) - log Z(w); log Z by exact inference (enumeration or elimination),
//    its gradient exactly: observed clause counts minus expected ones, E[n_c] = P(clause
//    c satisfied) from the exact marginals (a clause's cluster belief in the junction
//    tree; accumulated during enumeration).
//    Sampled expectations, where exact inference does not apply (a set-level choice:
//    Expectations::Auto uses the exact gradient when every training network's components
//    fit `exact`'s limits, otherwise sampled expectations for all sets; Exact refuses a
//    too-large network with an MlnError; Sampled forces sampling): E[n_c] is the fraction
//    of MC-SAT samples of the reweighted network that satisfy clause c. log Z is then
//    unknown, so there is no objective to line-search on; see LearnOptions::sampled_iterations.
// The exact optimiser is gradient ascent with Barzilai-Borwein steps and Armijo backtracking.
// The sampled one is a damped diagonal Newton method (Lowd & Domingos 2007): for a fixed
// number of iterations t = 1..T, each parameter moves by eta_t * g_j / hbar_j, g the
// per-world gradient (prior included) and hbar_j an exponential average (factor 0.8) of
// the earlier iterations' h_j = Var(n_j) + 1/(sigma^2 worlds), the diagonal of the negated
// Hessian from the sample variance of the parameter's count (the first iteration uses its
// own; not the current one after that, whose noise is correlated with g's); eta_t =
// 1/sqrt(t), each move clipped to [-1, 1]; MC-SAT seed `seed + t`. The result is the
// average of the iterates of the second half (Polyak averaging), deterministic for a seed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <string>

#include "runtime/mln/exact.h"
#include "runtime/mln/ground_network.h"

namespace ksmc::runtime::mln {

struct WeightTying {
  std::int32_t num_params = 0;
  std::vector<std::int32_t> param_of_clause;  // per program clause; -1: fixed
  std::vector<double> scale_of_clause;        // per program clause
};

struct TrainingSet {
  GroundNetwork network;
  std::vector<std::vector<std::uint8_t>> worlds;  // per world: a value per free network atom
};

enum class Objective { PseudoLikelihood, ConditionalLikelihood };
enum class Expectations { Auto, Exact, Sampled };  // the conditional likelihood's expected counts

struct LearnOptions {
  Objective objective = Objective::PseudoLikelihood;
  double prior_sigma = 10.0;      // L2 prior: -sum w^2 / (2 sigma^2)
  std::int32_t max_iterations = 2000;
  double tolerance = 1e-7;        // stop when the gradient's max norm (per world) is below
  // Conditional likelihood only:
  Expectations expectations = Expectations::Auto;
  ExactOptions exact;                    // the limits deciding whether exact inference applies
  std::int64_t samples = 1000;           // sampled: MC-SAT samples per gradient
  std::int64_t burn_in = 50;             // sampled: MC-SAT burn-in per gradient
  std::int32_t sampled_iterations = 100; // sampled: diagonal Newton iterations (fixed)
  std::uint64_t seed = 1;                // sampled: MC-SAT seed of iteration t is seed + t
};

struct LearnResult {
  std::vector<double> params;
  double objective = 0.0;         // per world, including the prior
  std::int32_t iterations = 0;
  bool converged = false;
  // Conditional likelihood: how the expected counts were computed, e.g. "exact gradient
  // (exact:enum 2)" or "sampled expectations (MC-SAT, 1000 samples)"; with sampled ones
  // `objective` is NaN and `converged` false (a fixed iteration count).
  std::string gradient;
  bool sampled = false;
  std::int32_t too_large_set = -1;  // Auto fell back to sampling: the first too-large set
  std::string too_large_reason;     // and its component, e.g. "a component of 154 free atoms (154 bits of state)"
};

// The conditional log-likelihood's data term (no prior) at `params`, summed over worlds,
// and its exact gradient (into `gradient`). Throws MlnError like learn_weights.
double conditional_log_likelihood(std::span<const TrainingSet> data, const WeightTying& tying,
                                  std::span<const double> params, std::vector<double>& gradient);

// Throws MlnError when a training world breaks a hard clause or an exactly-one block.
LearnResult learn_weights(std::span<const TrainingSet> data, const WeightTying& tying, std::vector<double> initial,
                          const LearnOptions& options = {});

}  // namespace ksmc::runtime::mln
