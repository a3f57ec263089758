#include "stdlib/tabletop/cloud_likelihood.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "stdlib/tabletop/line_of_sight.h"

namespace ksmc::stdlib::tabletop {

double signed_surface_distance(const Obb& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = in_box_axes(box, p - box.center);
  const Eigen::Vector3d excess = local.cwiseAbs() - box.half;  // > 0 outside along that axis
  if (excess.maxCoeff() > 0.0) return excess.cwiseMax(0.0).norm();
  return excess.maxCoeff();  // inside: minus the distance to the nearest face
}

double surface_distance(const Obb& box, const Eigen::Vector3d& p) { return std::abs(signed_surface_distance(box, p)); }

namespace {

// The face an inside point is not measured to: one that points down (its outward normal
// within 45 degrees of the table's -z; a box has at most one) with the sensor behind it. That
// is the face the box stands on, against the table or its supporter: no sensor above sees
// it. (The other faces the sensor cannot see stay: a can's or a bottle's silhouette lies on
// its box's side faces, seen edge-on.)
struct MeasuredFaces {
  int skip = -1;       // axis of the face left out, -1 for none
  double side = 0.0;   // +1: the face at +half along it, -1: at -half

  MeasuredFaces() = default;
  MeasuredFaces(const Obb& box, const Eigen::Vector3d& sensor_local) {
    constexpr double kDown = 0.7071;  // cos 45 deg
    for (int k = 0; k < 3; ++k) {
      const double up = box.axes(2, k);  // the table normal along axis k
      const double s = up < -kDown ? 1.0 : up > kDown ? -1.0 : 0.0;  // the face pointing down, if any
      if (s != 0.0 && !(s * sensor_local(k) > box.half(k))) skip = k, side = s;
    }
  }

  // Signed distance of a point (box axes, from its centre): outside, to the box; inside,
  // minus the distance to the nearest face but the one left out (none left out: as
  // signed_surface_distance).
  [[nodiscard]] double signed_distance(const Obb& box, const Eigen::Vector3d& local) const {
    const Eigen::Vector3d excess = local.cwiseAbs() - box.half;
    const double nearest = excess.maxCoeff();
    if (nearest > 0.0) return excess.cwiseMax(0.0).norm();
    if (skip < 0 || box.half(skip) - side * local(skip) > -nearest) return nearest;  // not the face left out
    double inside = box.half(skip) + side * local(skip);  // the opposite face
    for (int k = 0; k < 3; ++k)
      if (k != skip) inside = std::min(inside, -excess(k));
    return -inside;
  }
};

}  // namespace

double signed_seen_surface_distance(const Obb& box, const Eigen::Vector3d& p, const Eigen::Vector3d& sensor) {
  return MeasuredFaces(box, in_box_axes(box, sensor - box.center)).signed_distance(box, in_box_axes(box, p - box.center));
}

double cloud_log_likelihood(const Points& points, const Obb& box, const CloudLikelihoodParams& params) {
  const double norm = std::log(0.5 * (params.sigma + params.inside_sigma) * std::sqrt(2.0 * std::numbers::pi));
  const double inv_out = 1.0 / (2.0 * params.sigma * params.sigma);
  const double inv_in = 1.0 / (2.0 * params.inside_sigma * params.inside_sigma);
  const MeasuredFaces faces = params.sensor ? MeasuredFaces(box, in_box_axes(box, *params.sensor - box.center)) : MeasuredFaces();
  double sum = 0.0;
  for (const auto& p : points) {
    const double signed_d = faces.signed_distance(box, in_box_axes(box, p - box.center));
    const bool outside = signed_d > 0.0;
    double d = std::abs(signed_d);
    if (params.robust) d = std::min(d, params.outlier_distance);
    sum -= d * d * (outside ? inv_out : inv_in) + norm;
  }
  return sum;
}

std::size_t see_through_count(const Obb& box, const FreeSpace& fs) {
  const Eigen::Vector3d o = in_box_axes(box, fs.sensor - box.center);
  std::size_t count = 0;
  for (const auto& p : fs.points) count += segment_crosses(box, o, fs.sensor, p, fs.margin) ? 1 : 0;
  return count;
}

RayIndex::RayIndex(FreeSpace free_space, double cell) : fs_(std::move(free_space)), cell_(cell) {
  if (!(cell_ > 0.0)) throw std::invalid_argument("RayIndex: the cell must be > 0");
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : fs_.points) {
    const Eigen::Vector3d d = p - fs_.sensor;
    if (d.norm() > 0.0) mean += d.normalized();
  }
  const Eigen::Vector3d c = mean.norm() > 0.0 ? Eigen::Vector3d(mean.normalized()) : Eigen::Vector3d(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d e1 = c.unitOrthogonal();
  frame_.col(0) = e1;
  frame_.col(1) = c.cross(e1);
  frame_.col(2) = c;
  // Projected coordinates; rays at more than ~84 degrees from c are read on every query.
  std::vector<Eigen::Vector2d> uv(fs_.points.size());
  std::vector<char> front(fs_.points.size(), 0);
  double umin = 0.0, umax = 0.0, vmin = 0.0, vmax = 0.0;
  bool any = false;
  for (std::size_t i = 0; i < fs_.points.size(); ++i) {
    const Eigen::Vector3d l = frame_.transpose() * (fs_.points[i] - fs_.sensor);
    if (!(l.z() > 0.1 * l.norm())) {
      behind_.push_back(static_cast<std::uint32_t>(i));
      continue;
    }
    front[i] = 1;
    uv[i] = Eigen::Vector2d(l.x() / l.z(), l.y() / l.z());
    umin = any ? std::min(umin, uv[i].x()) : uv[i].x();
    umax = any ? std::max(umax, uv[i].x()) : uv[i].x();
    vmin = any ? std::min(vmin, uv[i].y()) : uv[i].y();
    vmax = any ? std::max(vmax, uv[i].y()) : uv[i].y();
    any = true;
  }
  // At most about a million cells: a wide view gets coarser cells.
  while (any && ((umax - umin) / cell_ + 1.0) * ((vmax - vmin) / cell_ + 1.0) > 1e6) cell_ *= 2.0;
  u0_ = umin;
  v0_ = vmin;
  nu_ = any ? static_cast<int>((umax - umin) / cell_) + 1 : 0;
  nv_ = any ? static_cast<int>((vmax - vmin) / cell_) + 1 : 0;
  std::vector<std::uint32_t> cell_of(fs_.points.size(), 0);
  start_.assign(static_cast<std::size_t>(nu_) * static_cast<std::size_t>(nv_) + 1, 0);
  for (std::size_t i = 0; i < fs_.points.size(); ++i) {
    if (!front[i]) continue;
    const int a = std::clamp(static_cast<int>((uv[i].x() - u0_) / cell_), 0, nu_ - 1);
    const int b = std::clamp(static_cast<int>((uv[i].y() - v0_) / cell_), 0, nv_ - 1);
    cell_of[i] = static_cast<std::uint32_t>(b * nu_ + a);
    ++start_[cell_of[i] + 1];
  }
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  order_.resize(fs_.points.size() - behind_.size());
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < fs_.points.size(); ++i)
    if (front[i]) order_[next[cell_of[i]]++] = static_cast<std::uint32_t>(i);
}

bool RayIndex::crosses(const Obb& box, const Eigen::Vector3d& origin_in_box, std::size_t ray) const {
  return segment_crosses(box, origin_in_box, fs_.sensor, fs_.points[ray], fs_.margin);
}

RayIndex::Toward RayIndex::cells_toward(const Obb& box, int& a0, int& a1, int& b0, int& b1) const {
  if (nu_ == 0) return Toward::none;
  double umin = 0.0, umax = 0.0, vmin = 0.0, vmax = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d l = frame_.transpose() * (box.vertex(k) - fs_.sensor);
    if (!(l.z() > 1e-9)) return Toward::all;  // reaches behind the view plane: every ray in front
    const double u = l.x() / l.z(), v = l.y() / l.z();
    umin = k == 0 ? u : std::min(umin, u);
    umax = k == 0 ? u : std::max(umax, u);
    vmin = k == 0 ? v : std::min(vmin, v);
    vmax = k == 0 ? v : std::max(vmax, v);
  }
  // Grid cells of the bounds, one cell of slack; clamped as doubles (no int overflow).
  const auto at = [this](double x, double origin, int n, int slack) {
    return static_cast<int>(std::clamp(std::floor((x - origin) / cell_) + slack, 0.0, static_cast<double>(n - 1)));
  };
  if (umax < u0_ - cell_ || vmax < v0_ - cell_ || umin > u0_ + (nu_ + 1) * cell_ || vmin > v0_ + (nv_ + 1) * cell_)
    return Toward::none;  // seen nowhere in the view
  a0 = at(umin, u0_, nu_, -1);
  a1 = at(umax, u0_, nu_, 1);
  b0 = at(vmin, v0_, nv_, -1);
  b1 = at(vmax, v0_, nv_, 1);
  return Toward::cells;
}

std::size_t RayIndex::see_through_count(const Obb& box) const {
  const Eigen::Vector3d o = in_box_axes(box, fs_.sensor - box.center);
  std::size_t count = 0;
  for_each_toward(box, [&](std::size_t r) { count += crosses(box, o, r) ? 1 : 0; });
  return count;
}

CloudLikelihood::CloudLikelihood(std::vector<Points> object_points, const std::vector<Obb>& boxes,
                                 CloudLikelihoodParams params, std::optional<FreeSpace> free_space)
    : points_(std::move(object_points)), params_(params) {
  if (free_space) free_space_.emplace(std::move(*free_space));
  if (points_.size() != boxes.size())
    throw std::invalid_argument("CloudLikelihood: one point set per box is needed");
  if (!(params_.sigma > 0.0) || !(params_.outlier_distance > 0.0))
    throw std::invalid_argument("CloudLikelihood: sigma and outlier_distance must be > 0");
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    terms_.push_back(evaluate(i, boxes[i]));
    total_ += terms_.back();
  }
}

double CloudLikelihood::evaluate(std::size_t object, const Obb& box) const {
  double term = cloud_log_likelihood(points_.at(object), box, params_);
  if (free_space_) term -= free_space_->free_space().cost * static_cast<double>(free_space_->see_through_count(box));
  return term;
}

double CloudLikelihood::update(std::size_t object, const Obb& box) {
  const double next = evaluate(object, box);
  const double delta = next - terms_[object];
  terms_[object] = next;
  total_ += delta;
  return delta;
}

}  // namespace ksmc::stdlib::tabletop
