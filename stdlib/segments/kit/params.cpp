#include "stdlib/segments/kit/params.h"

namespace ksmc::stdlib::segments::kit {

ModelParams model_params(const blocks::Binding& b) {
  ModelParams m;
  m.likelihood = std::get<blocks::PointsGaussian>(b.likelihood).params;
  m.priors = b.priors;
  for (const blocks::Prior& p : b.priors) m.mln_prior = m.mln_prior || std::holds_alternative<blocks::MlnPrior>(p);
  return m;
}

KernelParams kernel_params(const runtime::domain::KernelDecl<blocks::Move, blocks::Source>& k) {
  KernelParams p;
  p.move = k.move;
  for (const blocks::Source& s : k.sources) {
    if (const auto* r = std::get_if<blocks::Ransac>(&s)) {
      p.ransac = r->ransac;
      p.birth = r->birth;
      p.detects = true;
    } else if (const auto* d = std::get_if<blocks::PoorSupport>(&s)) {
      p.death = d->death;
    } else if (const auto* g = std::get_if<blocks::Gaps>(&s)) {
      p.split = g->split;
    } else if (const auto* m = std::get_if<blocks::InverseGap>(&s)) {
      p.merge = m->merge;
    } else if (const auto* j = std::get_if<blocks::EndpointJitter>(&s)) {
      p.jitter = j->jitter;
    }
  }
  return p;
}

}  // namespace ksmc::stdlib::segments::kit
