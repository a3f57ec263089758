#include "stdlib/tabletop/pose_proposal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

#include "stdlib/tabletop/rng.h"

namespace ksmc::stdlib::tabletop {

ProposalQ proposal_q(std::span<const double> candidate_log_weights, double current_log_weight) {
  ProposalQ q;
  constexpr double ninf = -std::numeric_limits<double>::infinity();
  double best_w = ninf;
  for (std::size_t i = 0; i < candidate_log_weights.size(); ++i) {
    if (candidate_log_weights[i] > best_w) {
      best_w = candidate_log_weights[i];
      q.best = static_cast<int>(i);
    }
  }
  // log(Σ_i w_i + w_0) by log-sum-exp.
  const double hi = std::max(best_w, current_log_weight);
  if (hi == ninf || std::isnan(hi)) {
    q.best = -1;
    q.log_q_forward = q.log_q_backward = ninf;
    return q;
  }
  double s = std::exp(current_log_weight - hi);
  for (double w : candidate_log_weights) s += std::exp(w - hi);
  const double log_total = hi + std::log(s);
  q.log_q_forward = q.best >= 0 ? best_w - log_total : ninf;
  q.log_q_backward = current_log_weight - log_total;
  return q;
}

Pose perturb_pose(const Pose& pose, double sigma_t, double sigma_r_rad, std::mt19937_64& rng) {
  Eigen::Vector3d dt;
  Eigen::Vector3d w;
  for (int i = 0; i < 3; ++i) dt[i] = sigma_t * standard_normal(rng);
  for (int i = 0; i < 3; ++i) w[i] = sigma_r_rad * standard_normal(rng);
  Pose out;
  out.t = pose.t + dt;
  const double angle = w.norm();
  const Eigen::Quaterniond dq =
      angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle)) : Eigen::Quaterniond::Identity();
  out.q = (dq * pose.q).normalized();
  return out;
}

PoseProposal propose_pose(const Scene& scene, std::size_t object_index, const PoseProposalParams& params,
                          const KeypointLikelihoodParams& likelihood, std::mt19937_64& rng) {
  if (object_index >= scene.objects.size()) throw std::out_of_range("propose_pose: object index out of range");
  if (params.candidates < 1) throw std::invalid_argument("propose_pose: candidates must be >= 1");
  if (!(params.sigma_t >= 0.0) || !(params.sigma_r_rad >= 0.0))
    throw std::invalid_argument("propose_pose: sigmas must be >= 0");
  const SceneObject& o = scene.objects[object_index];
  PoseProposal p;
  p.object = object_index;
  p.log_weight_current = keypoint_log_likelihood(scene, o, o.pose, likelihood);
  p.candidates.reserve(static_cast<std::size_t>(params.candidates));
  p.candidate_log_weights.reserve(static_cast<std::size_t>(params.candidates));
  for (int i = 0; i < params.candidates; ++i) {
    p.candidates.push_back(perturb_pose(o.pose, params.sigma_t, params.sigma_r_rad, rng));
    p.candidate_log_weights.push_back(keypoint_log_likelihood(scene, o, p.candidates.back(), likelihood));
  }
  const ProposalQ q = proposal_q(p.candidate_log_weights, p.log_weight_current);
  p.best = q.best;
  p.log_q_forward = q.log_q_forward;
  p.log_q_backward = q.log_q_backward;
  if (q.best < 0) {
    p.valid = false;
    p.reason = "no candidate has a non-zero keypoint likelihood";
    p.pose = o.pose;
    return p;
  }
  p.valid = true;
  p.pose = p.candidates[static_cast<std::size_t>(q.best)];
  p.log_weight_proposed = p.candidate_log_weights[static_cast<std::size_t>(q.best)];
  return p;
}

}  // namespace ksmc::stdlib::tabletop
