#include "stdlib/tabletop/perception/cloud_likelihood.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ksmc::stdlib::tabletop::perception {

double surface_distance(const Obb& box, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = box.axes.transpose() * (p - box.center);
  const Eigen::Vector3d excess = local.cwiseAbs() - box.half;  // > 0 outside along that axis
  if (excess.maxCoeff() > 0.0) return excess.cwiseMax(0.0).norm();
  return -excess.maxCoeff();  // inside: distance to the nearest face
}

double cloud_log_likelihood(const Points& points, const Obb& box, const CloudLikelihoodParams& params) {
  const double norm = std::log(params.sigma * std::sqrt(2.0 * std::numbers::pi));
  const double inv = 1.0 / (2.0 * params.sigma * params.sigma);
  double sum = 0.0;
  for (const auto& p : points) {
    double d = surface_distance(box, p);
    if (params.robust) d = std::min(d, params.outlier_distance);
    sum -= d * d * inv + norm;
  }
  return sum;
}

std::size_t see_through_count(const Obb& box, const FreeSpace& fs) {
  const Eigen::Vector3d o = box.axes.transpose() * (fs.sensor - box.center);
  std::size_t count = 0;
  for (const auto& p : fs.points) {
    const Eigen::Vector3d seg = p - fs.sensor;
    const double len = seg.norm();
    if (len <= fs.margin) continue;
    const double reach = 1.0 - fs.margin / len;  // segment parameter where the check stops
    const Eigen::Vector3d d = box.axes.transpose() * seg;
    double enter = 0.0, leave = reach;
    bool hit = true;
    for (int k = 0; k < 3 && hit; ++k) {
      if (std::abs(d[k]) < 1e-15) {
        hit = std::abs(o[k]) <= box.half[k];
        continue;
      }
      double s0 = (-box.half[k] - o[k]) / d[k], s1 = (box.half[k] - o[k]) / d[k];
      if (s0 > s1) std::swap(s0, s1);
      enter = std::max(enter, s0);
      leave = std::min(leave, s1);
      hit = enter <= leave;
    }
    count += hit ? 1 : 0;
  }
  return count;
}

CloudLikelihood::CloudLikelihood(std::vector<Points> object_points, const std::vector<Obb>& boxes,
                                 CloudLikelihoodParams params, std::optional<FreeSpace> free_space)
    : points_(std::move(object_points)), params_(params), free_space_(std::move(free_space)) {
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
  if (free_space_) term -= free_space_->cost * static_cast<double>(see_through_count(box, *free_space_));
  return term;
}

double CloudLikelihood::update(std::size_t object, const Obb& box) {
  const double next = evaluate(object, box);
  const double delta = next - terms_[object];
  terms_[object] = next;
  total_ += delta;
  return delta;
}

}  // namespace ksmc::stdlib::tabletop::perception
