// The DDMCMC `refine` move of §4.9 (pose.perturb): choose one object uniformly among the
// objects with observations (keypoints, or cloud points under `cloud.surface`; an object
// without any has a flat likelihood: moving it would follow the prior alone), draw
// `candidates` Gaussian perturbations of its pose (σ_t, σ_r), weight them and the current
// pose by the object's likelihood, and
// propose the best one. The current pose e_{t,0} is one of the weighted poses (its weight
// is in the denominator of eqs. 4.6/4.7); when it has the best weight the move keeps it
// (declined: M_{t+1} = M_t), so the likelihood of the moved object never decreases
// (KitOptions::current_competes; false proposes the best new candidate always).
// Q is eq. 4.6/4.7
// (stdlib/tabletop/pose_proposal.h: proposal_q) times the object choice 1/n in both
// directions (the reverse move picks the same object with the same probability, so the
// factor cancels in the ratio; it is included so log_q is the move's real selection
// probability). The kernel is its own reverse. A kernel declared with several pose.perturb
// sources picks one uniformly per move (a state-independent mixture of reversible moves).
#pragma once

#include <string>
#include <vector>

#include "runtime/mcmc/model.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/kit/tabletop_model.h"

namespace ksmc::stdlib::tabletop::kit {

class RefineKernel : public runtime::mcmc::NamedKernel<TabletopModel> {
 public:
  // `decl.move` must be Move::perturb and `decl.sources` non-empty (ConfigError otherwise).
  RefineKernel(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& decl, bool current_competes);
  const std::vector<blocks::PosePerturb>& sources() const noexcept { return sources_; }

 protected:
  runtime::mcmc::Proposal propose_typed(TabletopModel& model, runtime::mcmc::Rng& rng) const override;

 private:
  std::vector<blocks::PosePerturb> sources_;
  bool current_competes_ = true;
};

}  // namespace ksmc::stdlib::tabletop::kit
