#include "stdlib/tabletop/kit/fit_kernel.h"

#include <cmath>
#include <limits>
#include <random>

#include "runtime/domain/binding.h"
#include "stdlib/tabletop/keypoint_fit.h"

namespace ksmc::stdlib::tabletop::kit {

FitKernel::FitKernel(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& decl)
    : NamedKernel(decl.name, decl.reverse) {
  for (const auto& s : decl.sources)
    if (const auto* f = std::get_if<blocks::PoseFit>(&s)) sources_.push_back(*f);
  if (decl.move != blocks::Move::fit || sources_.empty() || sources_.size() != decl.sources.size())
    throw runtime::domain::ConfigError("kernel " + decl.name + ": the tabletop kit needs pose.fit sources");
  for (const auto& s : sources_)
    if (!(s.scale > 0.0)) throw runtime::domain::ConfigError("kernel " + decl.name + ": pose.fit needs scale > 0");
}

runtime::mcmc::Proposal FitKernel::propose_typed(TabletopModel& model, runtime::mcmc::Rng& rng) const {
  const std::vector<std::size_t>& movable = model.observed_objects();
  const std::size_t n = movable.size();
  if (n == 0) return runtime::mcmc::Proposal::declined();
  const std::size_t object = movable[static_cast<std::size_t>(rng.uniform_int(n))];
  const blocks::PoseFit& src =
      sources_.size() == 1 ? sources_[0] : sources_[static_cast<std::size_t>(rng.uniform_int(sources_.size()))];
  const KeypointFit& fit = model.block_scene().fit(blocks::Scene::body_of_object(object));
  if (!fit.ok) return runtime::mcmc::Proposal::declined();
  std::mt19937_64 mt(rng());
  const Pose current = model.scene().objects[object].pose;
  const Pose proposed = sample_fit(fit, src.scale, mt);
  const double log_pick = -std::log(static_cast<double>(n));
  const double fwd = fit_log_density(fit, src.scale, proposed) + log_pick;
  const double bwd = fit_log_density(fit, src.scale, current) + log_pick;
  model.begin_move(object, proposed, std::numeric_limits<double>::quiet_NaN());
  return runtime::mcmc::Proposal::made(fwd, bwd);
}

}  // namespace ksmc::stdlib::tabletop::kit
