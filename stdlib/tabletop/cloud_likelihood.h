// Cloud likelihood (`cloud.surface` of stdlib/tabletop.ksm; the --cloud front end's scenes):
// each point of an object's cluster is an observation of the box surface,
//     log p(p | box) = -d(p, surface)^2 / (2 s^2) - log((sigma + inside_sigma) / 2 sqrt(2 pi)),
// d = distance to the nearest face (inside the box, when the sensor is known, not to the face
// the box stands on: the sensor cannot see it), s = sigma outside the box and inside_sigma
// inside it:
// the box bounds an object that need not be a box (a can's or a bottle's front, a carton's
// gable top lie inside it), so a point inside costs less than one as far outside. The
// robust variant caps d at `outlier_distance` (a point that far costs a constant).
// Evaluated per object: a move of object i recomputes only i's term (CloudLikelihood keeps
// the per-object sums).
// With a FreeSpace, each object's term also loses `cost` per cloud ray its box blocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"

namespace ksmc::stdlib::tabletop {

using Points = std::vector<Eigen::Vector3d>;

struct CloudLikelihoodParams {
  double sigma = 0.004;              // m
  bool robust = true;
  double outlier_distance = 0.02;    // m, cap of d in the robust variant
  double inside_sigma = 0.02;        // m, scale of d for points inside the box
  // The sensor (same frame as the boxes), when known: a point inside a box is then not
  // measured to the face the box stands on, a face pointing down that the sensor is behind
  // (it lies on the table or its supporter, and no sensor above sees it). Measured to it, the
  // points of a mug's or a can's lower front (inside the box, near its bottom; the front end
  // leaves the lowest 12 mm to the table) pulled the box up off the table.
  std::optional<Eigen::Vector3d> sensor;
};

// Distance from p to the surface of the box (0 on a face, > 0 inside and outside).
double surface_distance(const Obb& box, const Eigen::Vector3d& p);
// The same with a sign: > 0 outside, < 0 inside.
double signed_surface_distance(const Obb& box, const Eigen::Vector3d& p);
// The same, but inside the box to the nearest face other than one pointing down (within
// 45 degrees) that `sensor` (same frame) is behind: the face the box stands on.
double signed_seen_surface_distance(const Obb& box, const Eigen::Vector3d& p, const Eigen::Vector3d& sensor);

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

// The same count, reading only the rays whose direction can meet the box: the rays are
// binned on a grid over the sensor's view (central projection onto the plane normal to
// their mean direction), and a box in front of the sensor is seen within the bounds of its
// projected corners. A box reaching behind the sensor's view plane reads every ray.
class RayIndex {
 public:
  RayIndex() = default;
  explicit RayIndex(FreeSpace free_space, double cell = 0.005);  // cell: grid step (tangent units)

  [[nodiscard]] std::size_t see_through_count(const Obb& box) const;
  [[nodiscard]] const FreeSpace& free_space() const noexcept { return fs_; }

  // Calls f(ray) for every ray (index into free_space().points) whose line from the sensor
  // may meet `box`: the rays binned within the bounds of its projected corners, or all of
  // them when it reaches behind the view plane. The lines go on past their points.
  template <class F>
  void for_each_toward(const Obb& box, F&& f) const {
    for (const std::uint32_t r : behind_) f(static_cast<std::size_t>(r));
    int a0 = 0, a1 = 0, b0 = 0, b1 = 0;
    switch (cells_toward(box, a0, a1, b0, b1)) {
      case Toward::none: return;
      case Toward::all:
        for (const std::uint32_t r : order_) f(static_cast<std::size_t>(r));
        return;
      case Toward::cells:
        for (int b = b0; b <= b1; ++b) {
          const std::size_t row = static_cast<std::size_t>(b) * static_cast<std::size_t>(nu_);
          for (std::size_t k = start_[row + static_cast<std::size_t>(a0)]; k < start_[row + static_cast<std::size_t>(a1) + 1]; ++k)
            f(static_cast<std::size_t>(order_[k]));
        }
    }
  }

 private:
  enum class Toward { none, all, cells };
  // The grid cells [a0, a1] x [b0, b1] that rays toward `box` are binned in (Toward::cells).
  Toward cells_toward(const Obb& box, int& a0, int& a1, int& b0, int& b1) const;
  bool crosses(const Obb& box, const Eigen::Vector3d& origin_in_box, std::size_t ray) const;

  FreeSpace fs_;
  Eigen::Matrix3d frame_ = Eigen::Matrix3d::Identity();  // columns e1, e2, c (c: mean direction)
  double cell_ = 0.005;
  double u0_ = 0.0, v0_ = 0.0;  // grid origin
  int nu_ = 0, nv_ = 0;
  std::vector<std::uint32_t> start_;  // per cell, into order_ (CSR, nu * nv + 1 entries)
  std::vector<std::uint32_t> order_;  // ray indices by cell
  std::vector<std::uint32_t> behind_; // rays not in front of the view plane: always read
};

// What the cloud front end saw, kept with its scene for `cloud.surface`: each object's own
// points and the whole cloud's rays (table frame).
struct CloudObservation {
  std::vector<Points> object_points;  // per scene object (file order)
  RayIndex rays;                      // empty (no ray) unless the domain prices free space
  std::optional<Eigen::Vector3d> sensor;  // the cloud's origin, when known
};

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
  std::optional<RayIndex> free_space_;
  double total_ = 0.0;
};

}  // namespace ksmc::stdlib::tabletop
