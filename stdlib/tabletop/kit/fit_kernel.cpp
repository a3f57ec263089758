#include "stdlib/tabletop/kit/fit_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "runtime/domain/binding.h"
#include "stdlib/tabletop/keypoint_fit.h"

namespace ksmc::stdlib::tabletop::kit {

FitKernel::FitKernel(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& decl, double estimate_sigma_t,
                     double estimate_sigma_r)
    : NamedKernel(decl.name, decl.reverse), estimate_sigma_t_(estimate_sigma_t), estimate_sigma_r_(estimate_sigma_r) {
  for (const auto& s : decl.sources)
    if (const auto* f = std::get_if<blocks::PoseFit>(&s)) sources_.push_back(*f);
  if (decl.move != blocks::Move::fit || sources_.empty() || sources_.size() != decl.sources.size())
    throw runtime::domain::ConfigError("kernel " + decl.name + ": the tabletop kit needs pose.fit sources");
  for (const auto& s : sources_) {
    if (!(s.scale > 0.0)) throw runtime::domain::ConfigError("kernel " + decl.name + ": pose.fit needs scale > 0");
    if (!(s.estimate_scale >= 0.0))
      throw runtime::domain::ConfigError("kernel " + decl.name + ": pose.fit needs estimate_scale >= 0");
    if (s.estimate_scale > 0.0 && !(estimate_sigma_t_ > 0.0 && estimate_sigma_r_ > 0.0))
      throw runtime::domain::ConfigError("kernel " + decl.name +
                                         ": pose.fit with estimate_scale > 0 needs the likelihood's pose-estimate term "
                                         "(keypoints.gaussian estimate_sigma_t and estimate_sigma_r above 0)");
  }
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
  const double log_pick = -std::log(static_cast<double>(n));
  if (src.estimate_scale > 0.0) {
    KeypointFit estimate;  // the input estimate as a Gaussian in the same tangent coordinates
    estimate.ok = true;
    estimate.mean = model.input_pose(object);
    const double t2 = estimate_sigma_t_ * estimate_sigma_t_, r2 = estimate_sigma_r_ * estimate_sigma_r_;
    estimate.covariance = Matrix6d::Zero();
    estimate.covariance.diagonal() << t2, t2, t2, r2, r2, r2;
    // The component draw comes first, from the move's own generator (reproducible).
    const bool from_fit = (mt() >> 63) == 0;
    const Pose proposed = from_fit ? sample_fit(fit, src.scale, mt) : sample_fit(estimate, src.estimate_scale, mt);
    auto log_q = [&](const Pose& p) {
      const double a = fit_log_density(fit, src.scale, p), b = fit_log_density(estimate, src.estimate_scale, p);
      const double m = std::max(a, b);
      if (m == -std::numeric_limits<double>::infinity()) return m;
      return m + std::log(0.5 * std::exp(a - m) + 0.5 * std::exp(b - m));
    };
    const double fwd = log_q(proposed) + log_pick, bwd = log_q(current) + log_pick;
    model.begin_move(object, proposed, std::numeric_limits<double>::quiet_NaN());
    return runtime::mcmc::Proposal::made(fwd, bwd);
  }
  const Pose proposed = sample_fit(fit, src.scale, mt);
  const double fwd = fit_log_density(fit, src.scale, proposed) + log_pick;
  const double bwd = fit_log_density(fit, src.scale, current) + log_pick;
  model.begin_move(object, proposed, std::numeric_limits<double>::quiet_NaN());
  return runtime::mcmc::Proposal::made(fwd, bwd);
}

}  // namespace ksmc::stdlib::tabletop::kit
