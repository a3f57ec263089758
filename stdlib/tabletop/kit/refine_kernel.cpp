#include "stdlib/tabletop/kit/refine_kernel.h"

#include <cmath>
#include <random>
#include <vector>

#include "stdlib/tabletop/pose_proposal.h"

namespace ksmc::stdlib::tabletop::kit {

RefineKernel::RefineKernel(RefineKernelConfig config)
    : NamedKernel(config.name, config.reverse), config_(std::move(config)) {}

runtime::mcmc::Proposal RefineKernel::propose_typed(TabletopModel& model, runtime::mcmc::Rng& rng) const {
  // Data-driven: only objects with keypoint observations can be refined (an object without
  // any has a flat likelihood, and moving it would follow the prior alone).
  const std::vector<std::size_t>& movable = model.observed_objects();
  const std::size_t n = movable.size();
  if (n == 0) return runtime::mcmc::Proposal::declined();
  const std::size_t object = movable[static_cast<std::size_t>(rng.uniform_int(n))];
  // The stdlib's portable perturbation runs on std::mt19937_64; seed one per move from the
  // chain's generator so the chain stays reproducible.
  std::mt19937_64 mt(rng());
  const Pose current = model.scene().objects[object].pose;
  std::vector<Pose> candidates;
  std::vector<double> weights;
  candidates.reserve(static_cast<std::size_t>(config_.candidates));
  weights.reserve(static_cast<std::size_t>(config_.candidates));
  for (int k = 0; k < config_.candidates; ++k) {
    candidates.push_back(perturb_pose(current, config_.sigma_t, config_.sigma_r, mt));
    weights.push_back(model.object_log_likelihood_at(object, candidates.back()));
  }
  const ProposalQ q = proposal_q(weights, model.object_log_likelihood(object));
  if (q.best < 0) return runtime::mcmc::Proposal::declined();
  const std::size_t best = static_cast<std::size_t>(q.best);
  // e_{t,0} has the best weight: it is the pose the move selects, and the state stays.
  if (config_.current_competes && !(weights[best] > model.object_log_likelihood(object)))
    return runtime::mcmc::Proposal::declined();
  model.begin_move(object, candidates[best], weights[best]);
  const double log_pick = -std::log(static_cast<double>(n));
  return runtime::mcmc::Proposal::made(q.log_q_forward + log_pick, q.log_q_backward + log_pick);
}

}  // namespace ksmc::stdlib::tabletop::kit
