// The keypoint-fit move (pose.fit): choose one object uniformly among the objects with
// keypoint observations and draw its new pose from N(fit mean, scale² Σ), the Laplace
// approximation of its keypoint likelihood (stdlib/tabletop/keypoint_fit.h, fitted once from
// the input estimate). The proposal does not depend on the current pose (an independence
// proposal), so Q(M'|M) and Q(M|M') are that density at the new and at the current pose,
// exactly; the object choice 1/n is the same both ways. The kernel is its own reverse.
#pragma once

#include "runtime/mcmc/model.h"
#include "stdlib/tabletop/blocks.h"
#include "stdlib/tabletop/kit/tabletop_model.h"

namespace ksmc::stdlib::tabletop::kit {

class FitKernel : public runtime::mcmc::NamedKernel<TabletopModel> {
 public:
  // `decl.move` must be Move::fit with pose.fit sources (ConfigError otherwise).
  explicit FitKernel(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& decl);

 protected:
  runtime::mcmc::Proposal propose_typed(TabletopModel& model, runtime::mcmc::Rng& rng) const override;

 private:
  std::vector<blocks::PoseFit> sources_;
};

}  // namespace ksmc::stdlib::tabletop::kit
