// Data-driven pose proposal of seed §4.9.
//
// For one object with current pose e0, draw n candidates e_i = e0 ⊕ noise
// (translation + N(0, σ_t² I), rotation exp(N(0, σ_r² I)) applied on the left, in
// the table frame), weight every pose by the keypoint likelihood (eq. 4.4), and
// propose the best candidate e*. The proposal probabilities are eqs. (4.6)/(4.7):
//   Q(M'|M) = w(e*) / (Σ_i w(e_i) + w(e0)),   Q(M|M') = w(e0) / (Σ_i w(e_i) + w(e0)),
// computed exactly in log space (log-sum-exp). See docs/tabletop.md on what these
// numbers are (the seed's heuristic, not the density of the argmax move).
#pragma once

#include <cstddef>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "stdlib/tabletop/likelihood.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct PoseProposalParams {
  int candidates = 20;                                 // n
  double sigma_t = 0.003;                              // [m] per axis
  double sigma_r_rad = 2.0 * 3.14159265358979323846 / 180.0;  // [rad] per axis of the rotation vector
};

struct ProposalQ {
  int best = -1;               // index of the best candidate (first on ties), -1 if none is finite
  double log_q_forward = 0.0;  // log Q(M'|M), eq. 4.6
  double log_q_backward = 0.0; // log Q(M|M'), eq. 4.7
};

// Eqs. 4.6/4.7 from the candidates' and the current pose's log weights.
ProposalQ proposal_q(std::span<const double> candidate_log_weights, double current_log_weight);

// One Gaussian perturbation of `pose` (the rng advances by 12 uniforms).
Pose perturb_pose(const Pose& pose, double sigma_t, double sigma_r_rad, std::mt19937_64& rng);

struct PoseProposal {
  bool valid = false;          // false: the kernel cannot apply (reason says why) — count as rejection
  std::string reason;
  std::size_t object = 0;      // index into scene.objects
  Pose pose;                   // proposed pose (table frame)
  double log_q_forward = 0.0;
  double log_q_backward = 0.0;
  double log_weight_current = 0.0;  // log w(e0)
  double log_weight_proposed = 0.0; // log w(e*)
  std::vector<Pose> candidates;
  std::vector<double> candidate_log_weights;
  int best = -1;
};

PoseProposal propose_pose(const Scene& scene, std::size_t object_index, const PoseProposalParams& params,
                          const KeypointLikelihoodParams& likelihood, std::mt19937_64& rng);

}  // namespace ksmc::stdlib::tabletop
