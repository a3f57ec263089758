#include "stdlib/indoor/kit/plan.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/domain/labels.h"

namespace ksmc::stdlib::indoor::kit {

namespace blk = blocks;
namespace dom = runtime::domain;

KernelKind kernel_kind(blk::Move m) {
  switch (m) {
    case blk::Move::birth: return KernelKind::Add;
    case blk::Move::death: return KernelKind::Remove;
    case blk::Move::split: return KernelKind::Split;
    case blk::Move::merge: return KernelKind::Merge;
    case blk::Move::shrink: return KernelKind::Shrink;
    case blk::Move::dilate: return KernelKind::Dilate;
    case blk::Move::allocate: return KernelKind::Allocate;
    case blk::Move::deallocate: return KernelKind::Delete;
    case blk::Move::interchange: return KernelKind::Interchange;
  }
  return KernelKind::Add;
}

namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// .ksm order (0 occupied, 1 unknown, 2 free) -> enum order (Free 0, Unknown 1, Wall/Occupied 2).
// The 3 x 3 shape is part of the signature `ksmc check` enforces.
LikelihoodTable to_table(const std::vector<std::vector<double>>& lut) {
  if (lut.size() != 3 || std::any_of(lut.begin(), lut.end(), [](const auto& r) { return r.size() != 3; }))
    throw dom::ConfigError("indoor kit (internal): grid.occupancy needs 3 x 3 tables");
  LikelihoodTable t;
  for (std::size_t w = 0; w < 3; ++w)
    for (std::size_t m = 0; m < 3; ++m) t.p[2 - w][2 - m] = lut[w][m];
  return t;
}

// A weight psi >= 0 of the .ksm (log prior -= psi per count) as the WeakPriorParams factor.
double factor_of(double psi) {
  const double f = std::exp(-psi);
  return std::clamp(f, std::numeric_limits<double>::min(), std::nextafter(1.0, 0.0));
}

// Several rect_penalty / overlap_penalty items add their weights; the smallest tolerance wins.
WeakPriorParams weak_prior(const std::vector<blk::Prior>& priors) {
  double psi1 = 0.0, psi2 = 0.0, tol = std::numeric_limits<double>::infinity();
  for (const auto& p : priors)
    std::visit(Overloaded{[&](const blk::RectPenalty& r) { psi1 += r.psi1; tol = std::min(tol, r.tol); },
                          [&](const blk::OverlapPenalty& o) { psi2 += o.psi2; },
                          [](const blk::MlnPrior&) {}},  // the semantic layer's (KitPlan::mln_prior)
               p);
  WeakPriorParams w;
  w.psi1 = factor_of(psi1);
  w.psi2 = factor_of(psi2);
  if (std::isfinite(tol)) w.angle_tolerance = tol;
  return w;
}

SourcePool pool_of(const std::vector<blk::Source>& sources) {
  SourcePool p;
  p.declared = sources;
  for (const auto& s : sources)
    std::visit(Overloaded{[&](const blk::detect::Wbu& x) { p.wbu.push_back(x); },
                          [&](const blk::detect::Fsu& x) { p.fsu.push_back(x); },
                          [&](const blk::detect::Rpb& x) { p.rpb.push_back(x); },
                          [&](const blk::detect::SplitLines& x) { p.split.push_back(x); },
                          [&](const blk::detect::Doors& x) { p.doors.push_back(x); },
                          [&](const blk::move::WallShift& x) { p.wall_shift.push_back(x); },
                          [](const blk::partner::InverseDistance&) {},  // the kernels' partner choice
                          [](const blk::move::Interchange&) {},
                          [&](const blk::move::UniformRect& x) { p.uniform_rect.push_back(x); },
                          [&](const blk::move::SeamDoors& x) { p.seam_doors.push_back(x); }},
               s);
  return p;
}

}  // namespace

KitPlan make_plan(const blk::Binding& b) {
  KitPlan plan;
  plan.tables = {to_table(b.likelihood.lut), to_table(b.likelihood.lenient_lut)};
  plan.prior = weak_prior(b.priors);
  for (const auto& k : b.kernels) {
    auto it = std::find_if(plan.pools.begin(), plan.pools.end(), [&](const SourcePool& p) { return p.declared == k.sources; });
    if (it == plan.pools.end()) it = plan.pools.insert(plan.pools.end(), pool_of(k.sources));
    plan.kernels.push_back({&k, kernel_kind(k.move), static_cast<std::size_t>(it - plan.pools.begin())});
  }
  plan.semantic = b.mln.program != nullptr;
  plan.mln_prior = plan.semantic && std::any_of(b.priors.begin(), b.priors.end(), [](const blk::Prior& p) {
                     return std::holds_alternative<blk::MlnPrior>(p);
                   });
  if (plan.semantic) {
    const auto groups = dom::label_groups(b.mln.program(), b.constant_type);
    if (!groups.empty()) plan.type_predicates = groups.front().predicates;
    for (std::int32_t q : plan.type_predicates)
      plan.lenient.push_back(std::find(b.likelihood.lenient_types.begin(), b.likelihood.lenient_types.end(), q) !=
                             b.likelihood.lenient_types.end());
  }
  const bool any_lenient = std::find(plan.lenient.begin(), plan.lenient.end(), true) != plan.lenient.end();
  plan.type_free_likelihood = !any_lenient || b.likelihood.lenient_lut == b.likelihood.lut;
  return plan;
}

}  // namespace ksmc::stdlib::indoor::kit
