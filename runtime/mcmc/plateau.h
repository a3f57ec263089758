// When has a run stopped improving? The best log posterior so far is a non-decreasing step
// function of the iteration. The run is on a plateau from iteration i when the best value
// `window` iterations later exceeds the best value at i by at most `min_gain`:
//     best(i + window) - best(i) <= min_gain.
// min_gain = 0 is the strict reading ("no gain over `window` iterations"). A positive min_gain
// ignores gains smaller than a stated unit, e.g. one_cell_gain(): the smallest change of
// log p(D|W) that corrects the prediction of a single cell (stdlib/indoor/likelihood.h), so
// that a plateau means "over `window` iterations, the best world explained less than one more
// cell".
//
// The detector is fed (iteration, best so far, wall seconds) in increasing iteration order, at
// any spacing (every iteration, or every trace row). Each fed point i is judged against the
// first point fed at or after i + window, so with a spacing of s iterations the plateau
// iteration is exact up to s. The engine (engine.h, EngineConfig::stop_at_plateau) feeds one
// detector per chain; bench/indoor/bench_indoor_run feeds two.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>

namespace ksmc::runtime::mcmc {

struct PlateauCriterion {
  std::uint64_t window = 5000;  // iterations
  double min_gain = 0.0;        // nats; gains <= min_gain over the window count as none
};

struct PlateauPoint {
  std::uint64_t iteration = 0;
  double best = 0.0;
  double seconds = 0.0;
};

class PlateauDetector {
 public:
  // Throws std::invalid_argument for window 0 or a negative / non-finite min_gain.
  explicit PlateauDetector(PlateauCriterion c);

  // Feeds one point; returns true once the plateau has been reached (also on later calls).
  // Throws std::invalid_argument when iterations do not increase or best decreases.
  bool observe(std::uint64_t iteration, double best, double seconds);

  bool reached() const { return plateau_.has_value(); }
  // The point where the plateau starts (i) and the point at which it became known (the first
  // point at or after i + window); nullopt before reached().
  const std::optional<PlateauPoint>& plateau() const { return plateau_; }
  const std::optional<PlateauPoint>& detected() const { return detected_; }
  const PlateauCriterion& criterion() const { return c_; }

 private:
  PlateauCriterion c_;
  std::deque<PlateauPoint> pending_;
  std::optional<PlateauPoint> last_, plateau_, detected_;
};

}  // namespace ksmc::runtime::mcmc
