#include "stdlib/tabletop/perception/box_fit.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Eigenvalues>

#include "stdlib/tabletop/perception/footprint.h"
#include "stdlib/tabletop/perception/planar_faces.h"
#include "stdlib/tabletop/perception/point_grid.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

double quantile_of(std::vector<double> v, double q) {
  const auto k = static_cast<std::size_t>(std::llround(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// The top: the median height of the band just under the robust highest point.
double top_of_heights(const std::vector<double>& z, const BoxFitOptions& options) {
  const double high = quantile_of(z, options.top_quantile);
  std::vector<double> band;
  for (double h : z)
    if (h >= high - options.top_band) band.push_back(h);
  return quantile_of(band, 0.5);
}

// A vertical face's trace on the table.
struct Wall {
  Eigen::Vector2d normal;  // unit
  Eigen::Vector2d point;   // a point of the trace (the mean of the face's points)
};

// The largest vertical planar face of `points`, when it holds options.wall_share of them (found
// on a copy thinned to options.wall_voxel, then refitted to all points within half a voxel of
// its plane and span): a box face, whose normal is one of the box's horizontal axes however the
// rest of the footprint is cut (by an occluder, by the image border). Nothing when there is none.
std::optional<Wall> find_wall(const Points& points, const BoxFitOptions& options) {
  const double voxel = options.wall_voxel;
  const Points sparse = voxel_subsample(points, voxel);
  FaceOptions fo;
  fo.normal_radius = fo.grow_radius = 2.0 * voxel;
  fo.min_points = 10;
  fo.plane_tolerance = 0.5 * voxel;
  const double min_points = std::max(10.0, options.wall_share * static_cast<double>(sparse.size()));
  for (const Face& f : planar_faces(sparse, fo)) {  // largest first
    if (static_cast<double>(f.points.size()) < min_points) break;
    if (std::abs(f.normal.z()) > std::sin(options.wall_tilt_deg * 3.14159265358979323846 / 180.0)) continue;
    const Eigen::Vector2d n = f.normal.head<2>().normalized(), along(-n.y(), n.x());
    const Eigen::Vector2d c = f.centroid.head<2>();
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, bottom = lo, top = -lo;
    for (int i : f.points) {
      const Eigen::Vector3d& p = sparse[static_cast<std::size_t>(i)];
      lo = std::min(lo, (p.head<2>() - c).dot(along)), hi = std::max(hi, (p.head<2>() - c).dot(along));
      bottom = std::min(bottom, p.z()), top = std::max(top, p.z());
    }
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector2d> on;
    for (const auto& p : points) {
      const Eigen::Vector2d d = p.head<2>() - c;
      if (std::abs(d.dot(n)) <= 0.5 * voxel && d.dot(along) >= lo && d.dot(along) <= hi && p.z() >= bottom &&
          p.z() <= top)
        on.push_back(d), mean += d;
    }
    if (on.size() < 2) return Wall{n, c};
    mean /= static_cast<double>(on.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();  // the face's trace on the table: a line
    for (const auto& d : on) cov += (d - mean) * (d - mean).transpose();
    return Wall{Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvectors().col(0), c + mean};
  }
  return std::nullopt;
}

// `rect` (along the wall) ends at the wall on the side the wall is nearer, when it reaches more
// than half a voxel past it: the wall is a face of the box, so the few points beyond it (at
// most wall_beyond of them: a real sensor's flying pixels along the depth edge) are not the
// box's. More points beyond it: the wall is inside a merged cluster, and the rectangle stays.
void end_at_wall(Rect2& rect, const std::vector<Eigen::Vector2d>& flat, const Wall& wall, const BoxFitOptions& options) {
  const int k = std::abs(rect.u.dot(wall.normal)) >= std::abs(rect.v().dot(wall.normal)) ? 0 : 1;
  const Eigen::Vector2d axis = k == 0 ? rect.u : rect.v();
  const double w = (wall.point - rect.center).dot(axis), half = rect.half[k];
  const double sign = w >= 0.0 ? 1.0 : -1.0;  // the side the wall is nearer
  if (half - sign * w <= 0.5 * options.wall_voxel) return;  // the side is at the wall but for noise
  std::size_t beyond = 0;
  for (const auto& q : flat) beyond += sign * ((q - rect.center).dot(axis) - w) > 0.5 * options.wall_voxel;
  if (static_cast<double>(beyond) > options.wall_beyond * static_cast<double>(flat.size())) return;
  const double lo = sign > 0.0 ? -half : w, hi = sign > 0.0 ? w : half;
  if (hi - lo <= 0.0) return;
  rect.center += 0.5 * (lo + hi) * axis;
  rect.half[k] = 0.5 * (hi - lo);
}

}  // namespace

double top_height(const Points& points, const BoxFitOptions& options) {
  std::vector<double> z;
  z.reserve(points.size());
  for (const auto& p : points) z.push_back(p.z());
  return top_of_heights(z, options);
}

UprightBox fit_upright_box(const Points& points, const BoxFitOptions& options) {
  std::vector<Eigen::Vector2d> flat;
  std::vector<double> z;
  flat.reserve(points.size());
  z.reserve(points.size());
  for (const auto& p : points) flat.emplace_back(p.x(), p.y()), z.push_back(p.z());
  Rect2 rect = options.side_faces_only ? faces_rect(flat, options.footprint_trim) : min_area_rect(flat, options.footprint_trim);
  if (options.wall_yaw && !options.side_faces_only) {
    // The minimal rectangle stays when one of its sides lies along the face (within
    // wall_agree_deg): it is the more precise.
    if (const std::optional<Wall> wall = find_wall(points, options)) {
      const Eigen::Vector2d& n = wall->normal;
      const double agree = std::cos(options.wall_agree_deg * 3.14159265358979323846 / 180.0);
      if (std::abs(n.dot(rect.u)) < agree && std::abs(n.dot(rect.v())) < agree) rect = rect_along(flat, n, options.footprint_trim);
      end_at_wall(rect, flat, *wall, options);
    }
  }

  const double top = top_of_heights(z, options);
  const double low = quantile_of(z, 0.01);
  const double bottom = low > options.float_gap ? low : 0.0;

  UprightBox b;
  b.size = Eigen::Vector3d(std::max(2.0 * rect.half.x(), options.min_size), std::max(2.0 * rect.half.y(), options.min_size),
                           std::max(top - bottom, options.min_size));
  b.pose.t = Eigen::Vector3d(rect.center.x(), rect.center.y(), bottom + 0.5 * b.size.z());
  const double yaw = std::atan2(rect.u.y(), rect.u.x());
  b.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return b;
}

}  // namespace ksmc::stdlib::tabletop::perception
