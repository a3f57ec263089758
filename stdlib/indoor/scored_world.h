// A world together with its incrementally maintained score against one classified map:
// likelihood (eq. 3.6, Table 3.1 with per-type tables), weak prior (eq. 3.3-3.5) and the cell
// prediction rate (eq. 3.39). apply(move) touches only the cells whose coverage changes and
// the unit pairs involving changed units; revert(move) restores the previous totals exactly
// (all bookkeeping is in integer counts, the log values are derived from them).
#pragma once

#include <cstdint>

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

  const World& world() const { return world_; }
  const ScoreParams& params() const { return params_; }
  const CoverageGrid& coverage() const { return grid_; }
  const ClassGrid& observed() const { return observed_; }

  // Applies the move (throws std::logic_error, leaving everything unchanged, if it does not fit).
  void apply(const Move& m);
  // Undoes a move previously applied (equivalent to apply(m.inverse())).
  void revert(const Move& m) { apply(m.inverse()); }
  // Replaces the world, rescoring from scratch.
  void reset(const World& w);

  double log_likelihood() const { return lik_.log_likelihood(grid_.histogram()); }
  double log_prior() const { return weak_log_prior(theta_, grid_.overlap(), params_.prior); }
  double log_posterior() const { return log_likelihood() + log_prior(); }
  std::int64_t misaligned_pairs() const { return theta_; }
  std::int64_t overlap_cells() const { return grid_.overlap(); }
  double cell_prediction_rate() const { return indoor::cell_prediction_rate(grid_.histogram()); }

  // From-scratch recomputations, for verification.
  double recompute_log_likelihood() const;
  double recompute_log_prior() const;

 private:
  UnitRaster unit_raster(const Unit& u) const;
  SpanRaster door_raster(const Door& d) const;

  ClassGrid observed_;
  ScoreParams params_;
  LikelihoodModel lik_;
  CoverageGrid grid_;
  World world_;
  std::int64_t theta_ = 0;
};

}  // namespace ksmc::stdlib::indoor
