#include "stdlib/tabletop/kit/refine_kernel.h"

#include <cmath>
#include <random>
#include <vector>

#include "runtime/domain/binding.h"
#include "stdlib/tabletop/pose_proposal.h"

namespace ksmc::stdlib::tabletop::kit {

RefineKernel::RefineKernel(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& decl, bool current_competes)
    : NamedKernel(decl.name, decl.reverse), current_competes_(current_competes) {
  for (const auto& s : decl.sources)
    if (const auto* p = std::get_if<blocks::PosePerturb>(&s)) sources_.push_back(*p);
  if (decl.move != blocks::Move::perturb || sources_.empty() || sources_.size() != decl.sources.size())
    throw runtime::domain::ConfigError("kernel " + decl.name + ": the tabletop kit needs pose.perturb sources");
  for (const auto& s : sources_)
    if (!(s.sigma_t > 0.0) || !(s.sigma_r > 0.0) || s.candidates < 1)
      throw runtime::domain::ConfigError("kernel " + decl.name + ": pose.perturb needs sigma_t, sigma_r > 0 and candidates >= 1");
}

runtime::mcmc::Proposal RefineKernel::propose_typed(TabletopModel& model, runtime::mcmc::Rng& rng) const {
  // Data-driven: only objects with observations (keypoints, or cloud points under
  // `cloud.surface`) can be refined (an object without any has a flat likelihood, and
  // moving it would follow the prior alone).
  const std::vector<std::size_t>& movable = model.observed_objects();
  const std::size_t n = movable.size();
  if (n == 0) return runtime::mcmc::Proposal::declined();
  const std::size_t object = movable[static_cast<std::size_t>(rng.uniform_int(n))];
  // One source per move when several are declared; the common single source costs no draw,
  // so chains of a one-source kernel stay what they were.
  const blocks::PosePerturb& src =
      sources_.size() == 1 ? sources_[0] : sources_[static_cast<std::size_t>(rng.uniform_int(sources_.size()))];
  // The stdlib's portable perturbation runs on std::mt19937_64; seed one per move from the
  // chain's generator so the chain stays reproducible.
  std::mt19937_64 mt(rng());
  const Pose current = model.scene().objects[object].pose;
  std::vector<Pose> candidates;
  std::vector<double> weights;
  candidates.reserve(static_cast<std::size_t>(src.candidates));
  weights.reserve(static_cast<std::size_t>(src.candidates));
  for (int k = 0; k < src.candidates; ++k) {
    candidates.push_back(perturb_pose(current, src.sigma_t, src.sigma_r, mt));
    weights.push_back(model.object_log_likelihood_at(object, candidates.back()));
  }
  const ProposalQ q = proposal_q(weights, model.object_log_likelihood(object));
  if (q.best < 0) return runtime::mcmc::Proposal::declined();
  const std::size_t best = static_cast<std::size_t>(q.best);
  // e_{t,0} has the best weight: it is the pose the move selects, and the state stays.
  if (current_competes_ && !(weights[best] > model.object_log_likelihood(object)))
    return runtime::mcmc::Proposal::declined();
  model.begin_move(object, candidates[best], weights[best]);
  const double log_pick = -std::log(static_cast<double>(n));
  return runtime::mcmc::Proposal::made(q.log_q_forward + log_pick, q.log_q_backward + log_pick);
}

}  // namespace ksmc::stdlib::tabletop::kit
