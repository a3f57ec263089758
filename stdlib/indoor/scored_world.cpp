#include "stdlib/indoor/scored_world.h"

#include <algorithm>
#include <array>

namespace ksmc::stdlib::indoor {

ScoredWorld::ScoredWorld(const ClassGrid& observed, ScoreParams params)
    : observed_(observed.clone()), params_(std::move(params)), lik_(params_.tables), grid_(observed_) {
  params_.prior.validate();
}

UnitRaster ScoredWorld::unit_raster(const Unit& u) const {
  return UnitRaster(u.rect, params_.raster.wall_thickness, grid_.cols());
}

SpanRaster ScoredWorld::door_raster(const Door& d) const {
  return SpanRaster(door_rect(d.a, d.b, params_.raster.door_depth_or_default()), grid_.cols());
}

std::size_t ScoredWorld::footprints(const Move& m, std::array<UnitRaster, CoverageGrid::kMaxJointFootprints>& rs,
                                    std::array<CoverageGrid::Footprint, CoverageGrid::kMaxJointFootprints>& fs) const {
  std::size_t n = 0;
  for (const auto& c : m.units) {
    if (c.before) {
      rs[n] = unit_raster(*c.before);
      fs[n] = {&rs[n], c.before->lut_class, -1};
      ++n;
    }
    if (c.after) {
      rs[n] = unit_raster(*c.after);
      fs[n] = {&rs[n], c.after->lut_class, +1};
      ++n;
    }
  }
  return n;
}

Histogram ScoredWorld::histogram() const {
  Histogram h = grid_.histogram();
  if (pending_)
    for (std::size_t i = 0; i < h.size(); ++i) h[i] += pending_->delta.hist[i];
  return h;
}

double ScoredWorld::log_likelihood() const {
  return pending_ ? lik_.log_likelihood(histogram()) : lik_.log_likelihood(grid_.histogram());
}

bool ScoredWorld::preview(const Move& m) {
  if (pending_) throw std::logic_error("ScoredWorld::preview: a preview is already open");
  if (!m.doors.empty() || 2 * m.units.size() > CoverageGrid::kMaxJointFootprints) return false;
  std::vector<UnitId> ids;
  ids.reserve(m.units.size());
  for (const auto& c : m.units) {
    if (c.after && c.after->lut_class >= kMaxLutClasses)
      throw std::logic_error("ScoredWorld::apply: unit " + std::to_string(c.id) + " has lut class out of range");
    if (std::find(ids.begin(), ids.end(), c.id) == ids.end()) ids.push_back(c.id);
  }
  Pending p;
  p.world = world_.applied(m);  // throws before anything changes when the move misfits
  std::array<UnitRaster, CoverageGrid::kMaxJointFootprints> rs;
  std::array<CoverageGrid::Footprint, CoverageGrid::kMaxJointFootprints> fs;
  const std::size_t n = footprints(m, rs, fs);
  p.delta = grid_.preview_units(std::span<const CoverageGrid::Footprint>(fs.data(), n));
  p.theta = theta_ + misaligned_pairs_involving(p.world, ids, params_.prior) -
            misaligned_pairs_involving(world_, ids, params_.prior);
  p.move = m;
  pending_ = std::move(p);
  return true;
}

void ScoredWorld::commit() {
  if (!pending_) throw std::logic_error("ScoredWorld::commit: no preview open");
  Pending p = std::move(*pending_);
  pending_.reset();
  apply(p.move);
}

void ScoredWorld::apply(const Move& m) {
  if (pending_) throw std::logic_error("ScoredWorld::apply: a preview is open (commit or discard it first)");
  std::vector<UnitId> ids;
  ids.reserve(m.units.size());
  for (const auto& c : m.units)
    if (std::find(ids.begin(), ids.end(), c.id) == ids.end()) ids.push_back(c.id);
  for (const auto& c : m.units) {
    if (c.after && c.after->lut_class >= kMaxLutClasses)
      throw std::logic_error("ScoredWorld::apply: unit " + std::to_string(c.id) +
                             " has lut class out of range");
  }
  const std::int64_t theta_before = misaligned_pairs_involving(world_, ids, params_.prior);
  World next = world_.applied(m);  // throws before anything changes when the move misfits
  if (2 * m.units.size() <= CoverageGrid::kMaxJointFootprints) {
    // One sweep over all footprints: cells whose counts do not change in total (the shared
    // area of a split or merge) are not visited.
    std::array<UnitRaster, CoverageGrid::kMaxJointFootprints> rs;
    std::array<CoverageGrid::Footprint, CoverageGrid::kMaxJointFootprints> fs;
    const std::size_t n = footprints(m, rs, fs);
    grid_.update_units(std::span<const CoverageGrid::Footprint>(fs.data(), n));
  } else {
    for (const auto& c : m.units) {
      UnitRaster b, a;
      if (c.before) b = unit_raster(*c.before);
      if (c.after) a = unit_raster(*c.after);
      grid_.update_unit(c.before ? &b : nullptr, c.before ? c.before->lut_class : 0,
                        c.after ? &a : nullptr, c.after ? c.after->lut_class : 0);
    }
  }
  for (const auto& c : m.doors) {
    SpanRaster b, a;
    if (c.before) b = door_raster(*c.before);
    if (c.after) a = door_raster(*c.after);
    grid_.update_door(c.before ? &b : nullptr, c.after ? &a : nullptr);
  }
  world_ = std::move(next);
  theta_ += misaligned_pairs_involving(world_, ids, params_.prior) - theta_before;
}

void ScoredWorld::reset(const World& w) {
  pending_.reset();
  grid_ = CoverageGrid(observed_);
  world_ = World();
  Move all;
  for (const Unit& u : w.units()) all.units.push_back({u.id, std::nullopt, u});
  for (const Door& d : w.doors()) all.doors.push_back({d.id, std::nullopt, d});
  apply(all);
  world_ = w;  // keeps the id counters of `w`
}

double ScoredWorld::recompute_log_likelihood() const {
  return full_score(observed_, world(), lik_, params_.raster).log_likelihood;
}

double ScoredWorld::recompute_log_prior() const {
  const FullScore f = full_score(observed_, world(), lik_, params_.raster);
  return weak_log_prior(misaligned_pairs_total(world(), params_.prior), f.overlap, params_.prior);
}

}  // namespace ksmc::stdlib::indoor
