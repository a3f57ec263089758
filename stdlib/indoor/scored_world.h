// A world together with its incrementally maintained score against one classified map:
// likelihood (eq. 3.6, Table 3.1 with per-type tables), weak prior (eq. 3.3-3.5) and the cell
// prediction rate (eq. 3.39). apply(move) touches only the cells whose coverage changes and
// the unit pairs involving changed units; revert(move) restores the previous totals exactly
// (all bookkeeping is in integer counts, the log values are derived from them).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "stdlib/indoor/coverage.h"
#include "stdlib/indoor/likelihood.h"
#include "stdlib/indoor/prior.h"
#include "stdlib/indoor/world.h"

namespace ksmc::stdlib::indoor {

struct ScoreParams {
  RasterParams raster;
  std::vector<LikelihoodTable> tables{LikelihoodTable::table_3_1()};
  WeakPriorParams prior;
};

class ScoredWorld {
 public:
  ScoredWorld(const ClassGrid& observed, ScoreParams params);

  // The world; while a preview is open, the previewed world.
  const World& world() const { return pending_ ? pending_->world : world_; }
  const ScoreParams& params() const { return params_; }
  const CoverageGrid& coverage() const { return grid_; }
  const ClassGrid& observed() const { return observed_; }

  // Applies the move (throws std::logic_error, leaving everything unchanged, if it does not fit).
  void apply(const Move& m);
  // Scores `m` without touching the coverage grid: until commit() or discard(), world(),
  // log_likelihood() and log_prior() read as if `m` were applied (coverage() does not).
  // commit() then applies it (same totals, bit for bit); discard() forgets it, so a rejected
  // proposal costs one read-only sweep instead of an apply and a revert. Only moves of units
  // (no doors, at most kMaxJointFootprints / 2 unit changes) can be previewed: for any other
  // move preview() returns false and does nothing. Throws like apply() on a misfit.
  bool preview(const Move& m);
  bool previewing() const { return pending_.has_value(); }
  void commit();
  void discard() { pending_.reset(); }
  // Undoes a move previously applied (equivalent to apply(m.inverse())).
  void revert(const Move& m) { apply(m.inverse()); }
  // Replaces the world, rescoring from scratch.
  void reset(const World& w);

  double log_likelihood() const;
  double log_prior() const {
    return pending_ ? weak_log_prior(pending_->theta, grid_.overlap() + pending_->delta.overlap, params_.prior)
                    : weak_log_prior(theta_, grid_.overlap(), params_.prior);
  }
  double log_posterior() const { return log_likelihood() + log_prior(); }
  std::int64_t misaligned_pairs() const { return pending_ ? pending_->theta : theta_; }
  std::int64_t overlap_cells() const { return grid_.overlap() + (pending_ ? pending_->delta.overlap : 0); }
  double cell_prediction_rate() const { return indoor::cell_prediction_rate(histogram()); }
  // Cell histogram (including an open preview).
  Histogram histogram() const;

  // From-scratch recomputations, for verification.
  double recompute_log_likelihood() const;
  double recompute_log_prior() const;

 private:
  UnitRaster unit_raster(const Unit& u) const;
  // Footprints of the unit changes of `m` into rs / fs; returns how many.
  std::size_t footprints(const Move& m, std::array<UnitRaster, CoverageGrid::kMaxJointFootprints>& rs,
                         std::array<CoverageGrid::Footprint, CoverageGrid::kMaxJointFootprints>& fs) const;
  SpanRaster door_raster(const Door& d) const;

  ClassGrid observed_;
  ScoreParams params_;
  LikelihoodModel lik_;
  CoverageGrid grid_;
  World world_;
  std::int64_t theta_ = 0;
  struct Pending {
    Move move;
    World world;
    CoverageGrid::Delta delta;
    std::int64_t theta = 0;
  };
  std::optional<Pending> pending_;
};

}  // namespace ksmc::stdlib::indoor
