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
//    tree; accumulated during enumeration). Only for networks exact inference can solve
//    (otherwise an MlnError).
// The optimiser is gradient ascent with Barzilai-Borwein steps and Armijo backtracking.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

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

struct LearnOptions {
  Objective objective = Objective::PseudoLikelihood;
  double prior_sigma = 10.0;      // L2 prior: -sum w^2 / (2 sigma^2)
  std::int32_t max_iterations = 2000;
  double tolerance = 1e-7;        // stop when the gradient's max norm (per world) is below
};

struct LearnResult {
  std::vector<double> params;
  double objective = 0.0;         // per world, including the prior
  std::int32_t iterations = 0;
  bool converged = false;
};

// The conditional log-likelihood's data term (no prior) at `params`, summed over worlds,
// and its exact gradient (into `gradient`). Throws MlnError like learn_weights.
double conditional_log_likelihood(std::span<const TrainingSet> data, const WeightTying& tying,
                                  std::span<const double> params, std::vector<double>& gradient);

// Throws MlnError when a training world breaks a hard clause or an exactly-one block.
LearnResult learn_weights(std::span<const TrainingSet> data, const WeightTying& tying, std::vector<double> initial,
                          const LearnOptions& options = {});

}  // namespace ksmc::runtime::mln
