// The keypoint-fit move (pose.fit): choose one object uniformly among the objects with
// keypoint observations and draw its new pose from N(fit mean, scale² Σ), the Laplace
// approximation of its keypoint likelihood (stdlib/tabletop/keypoint_fit.h, fitted once from
// the input estimate). With estimate_scale > 0, the pose is drawn with probability 1/2 from
// that and with probability 1/2 from N(input estimate, estimate_scale² diag(σ_t², σ_r²)) (σ the
// likelihood's pose-estimate term), and the density is the mixture's. The proposal does not
// depend on the current pose (an independence proposal), so Q(M'|M) and Q(M|M') are its
// density at the new and at the current pose, exactly; the object choice 1/n is the same both
// ways. The kernel is its own reverse.
//
// Why the mixture: an independence move from a state x is accepted with
// π(y) q(x) / (π(x) q(y)). A state near a poor input estimate, where the robust keypoint
// likelihood is flat (every residual at its cap) and the refine move finds no way up, lies
// far in the keypoint fit's tails: q(x) is so small that the fit's far better pose is never
// accepted. The estimate part keeps q(x) at the estimate's own scale.
#pragma once

#include "runtime/mcmc/model.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/kit/tabletop_model.h"

namespace ksmc::stdlib::tabletop::kit {

class FitKernel : public runtime::mcmc::NamedKernel<TabletopModel> {
 public:
  // `decl.move` must be Move::fit with pose.fit sources (ConfigError otherwise).
  // `estimate_sigma_t` [m] / `estimate_sigma_r` [rad]: the likelihood's pose-estimate term,
  // above 0 when a source has estimate_scale > 0 (ConfigError otherwise).
  FitKernel(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& decl, double estimate_sigma_t,
            double estimate_sigma_r);

 protected:
  runtime::mcmc::Proposal propose_typed(TabletopModel& model, runtime::mcmc::Rng& rng) const override;

 private:
  std::vector<blocks::PoseFit> sources_;
  double estimate_sigma_t_ = 0.0, estimate_sigma_r_ = 0.0;
};

}  // namespace ksmc::stdlib::tabletop::kit
