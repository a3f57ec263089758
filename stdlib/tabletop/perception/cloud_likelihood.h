// Cloud likelihood for scenes without keypoints: each point of an object's cluster is a
// Gaussian observation of the box surface,
//     log p(p | box) = -d(p, surface)^2 / (2 sigma^2) - log(sigma sqrt(2 pi)),
// d = distance to the nearest face (inside or outside the box). The robust variant caps d
// at `outlier_distance` (a point that far costs a constant). Evaluated per object: a move
// of object i recomputes only i's term (CloudLikelihood keeps the per-object sums).
// With a FreeSpace, each object's term also loses `cost` per cloud ray its box blocks.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/perception/cloud_io.h"

namespace ksmc::stdlib::tabletop::perception {

struct CloudLikelihoodParams {
  double sigma = 0.004;              // m
  bool robust = true;
  double outlier_distance = 0.02;    // m, cap of d in the robust variant
};

// Distance from p to the surface of the box (0 on a face, > 0 inside and outside).
double surface_distance(const Obb& box, const Eigen::Vector3d& p);

// Sum over `points` (same frame as the box). An empty point set gives 0.
double cloud_log_likelihood(const Points& points, const Obb& box, const CloudLikelihoodParams& params = {});

// Free space: every point of the cloud was seen along the ray from the sensor, so a box that
// the ray crosses (more than `margin` before the point) cannot be there. This is what
// penalises a box where the sensor sees through it (a false estimate in free space),
// which the surface term alone cannot: such a box has no points of its own.
struct FreeSpace {
  Points points;                                // the whole cloud, same frame as the boxes
  Eigen::Vector3d sensor = Eigen::Vector3d::Zero();
  double margin = 0.01;                         // m kept free before each point (its own surface)
  double cost = 12.5;                           // log-likelihood lost per crossed ray
};

// Number of rays sensor -> point that pass through the box before point - margin.
std::size_t see_through_count(const Obb& box, const FreeSpace& free_space);

// Incremental evaluation over the objects of a scene (table frame).
class CloudLikelihood {
 public:
  CloudLikelihood(std::vector<Points> object_points, const std::vector<Obb>& boxes, CloudLikelihoodParams params = {},
                  std::optional<FreeSpace> free_space = std::nullopt);

  [[nodiscard]] double total() const { return total_; }
  [[nodiscard]] double term(std::size_t object) const { return terms_.at(object); }
  [[nodiscard]] std::size_t size() const { return terms_.size(); }
  // Log-likelihood of object i's points at `box`, without changing the state.
  [[nodiscard]] double evaluate(std::size_t object, const Obb& box) const;
  // Moves object i to `box`; returns the change of the total.
  double update(std::size_t object, const Obb& box);

 private:
  std::vector<Points> points_;
  std::vector<double> terms_;
  CloudLikelihoodParams params_;
  std::optional<FreeSpace> free_space_;
  double total_ = 0.0;
};

}  // namespace ksmc::stdlib::tabletop::perception
