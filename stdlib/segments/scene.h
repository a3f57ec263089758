// The segment set of a model and the points' likelihood `points.gaussian(sigma, background)`,
// maintained incrementally: every point keeps its nearest segment and distance, and a change
// (some segments removed, some added) re-scores only the points whose nearest segment was
// removed (against all segments) and compares the others with the added segments.
//
//   log p(x_i | M) = log((1 - background) exp(-d_i^2 / (2 sigma^2)) + background)
//
// with d_i the distance from x_i to its nearest segment (infinite when there is none).
// A change is tentative until commit(); rollback() restores the state bit for bit.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "stdlib/segments/geometry.h"

namespace ksmc::stdlib::segments {

struct LikelihoodParams {
  double sigma = 0.02;       // metres
  double background = 0.05;  // in (0, 1)
};

// One segment of the model with a stable id (for outputs; not part of the density).
struct Line {
  Segment seg;
  std::uint64_t id = 0;
};

class Scene {
 public:
  Scene(std::shared_ptr<const std::vector<Vec2>> points, LikelihoodParams params);

  const std::vector<Vec2>& points() const { return *points_; }
  const LikelihoodParams& params() const { return params_; }
  const std::vector<Line>& lines() const { return lines_; }
  std::size_t size() const { return lines_.size(); }

  double log_likelihood() const { return total_; }
  // Per point: index of the nearest line (-1: none) and the distance (inf: none).
  int nearest(std::size_t i) const { return nearest_[i]; }
  double distance(std::size_t i) const { return dist_[i]; }

  // The log-likelihood term of a point at distance d (d = inf: background only).
  double term(double d) const;

  // Tentative change: removes the lines at `remove` (indices, any order, distinct) and
  // appends `add` (each canonicalised and given a fresh id). The surviving lines keep their
  // order. `ids` (empty, or one per added line) keeps given ids instead of fresh ones.
  // Returns the indices of the added lines. One change at a time.
  std::vector<std::size_t> change(std::span<const std::size_t> remove, std::span<const Segment> add,
                                  std::span<const std::uint64_t> ids = {});
  void commit();
  void rollback();
  bool pending() const { return pending_; }

  // Replaces everything (no pending change) and recomputes from scratch.
  void reset(std::vector<Line> lines, std::uint64_t next_id);
  std::uint64_t next_id() const { return next_id_; }

  // Full recomputation of the likelihood of the current lines (for checks): sum of terms.
  double recompute_log_likelihood() const;

 private:
  void full_assign();

  std::shared_ptr<const std::vector<Vec2>> points_;
  LikelihoodParams params_;
  double inv_two_sigma2_ = 0.0, log_bg_ = 0.0;
  std::vector<Line> lines_;
  std::vector<int> nearest_;
  std::vector<double> dist_;
  std::vector<double> terms_;
  double total_ = 0.0;
  std::uint64_t next_id_ = 0;

  struct Backup {
    std::vector<Line> lines;
    std::vector<int> nearest;
    std::vector<double> dist, terms;
    double total = 0.0;
    std::uint64_t next_id = 0;
  };
  bool pending_ = false;
  Backup backup_;
};

}  // namespace ksmc::stdlib::segments
