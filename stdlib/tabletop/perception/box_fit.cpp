#include "stdlib/tabletop/perception/box_fit.h"

#include <algorithm>
#include <cmath>

#include "stdlib/tabletop/perception/footprint.h"

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
  const Rect2 rect = options.side_faces_only ? faces_rect(flat, options.footprint_trim) : min_area_rect(flat, options.footprint_trim);

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
