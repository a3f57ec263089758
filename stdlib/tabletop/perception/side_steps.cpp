#include "stdlib/tabletop/perception/side_steps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>

#include "stdlib/tabletop/perception/footprint.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

double median(std::vector<double> v) { return quantile(v, 0.5); }

double mad(const std::vector<double>& v) {
  const double m = median(v);
  std::vector<double> d;
  d.reserve(v.size());
  for (double x : v) d.push_back(std::abs(x - m));
  return median(std::move(d));
}

struct Bin {
  double z;      // centre height
  double level;  // median signed distance to the top's outline
};

// A run of bins at one level, from the top down.
struct Run {
  std::vector<double> levels;
  double lowest_z = 0.0, highest_z = 0.0;

  [[nodiscard]] double level(int last) const {
    const auto n = std::min<std::size_t>(levels.size(), static_cast<std::size_t>(last));
    return median(std::vector<double>(levels.end() - static_cast<std::ptrdiff_t>(n), levels.end()));
  }
};

// Per face of the top's outline and per height bin (bins with enough points), from the top
// down: the median signed distance of the side points nearest that face to its line
// (outward positive). Per face, since occlusion changes which faces are seen with height.
// Empty when the top face has too few points.
std::vector<std::vector<Bin>> side_profiles(const Points& points, double bottom, double top, const SideStepOptions& o,
                                            double trim) {
  std::vector<Eigen::Vector2d> top_face;
  for (const auto& p : points)
    if (p.z() >= top - o.top_band) top_face.emplace_back(p.x(), p.y());
  if (top_face.size() < o.min_top_points) return {};
  const Rect2 outline = min_area_rect(top_face, trim);
  std::array<std::map<long, std::vector<double>, std::greater<>>, 4> bins;
  for (const auto& p : points) {
    if (p.z() < bottom + o.bin || p.z() >= top - o.top_band) continue;
    const Eigen::Vector2d d = Eigen::Vector2d(p.x(), p.y()) - outline.center;
    const double a = d.dot(outline.u), b = d.dot(outline.v());
    const std::array<double, 4> out{a - outline.half.x(), -a - outline.half.x(), b - outline.half.y(), -b - outline.half.y()};
    std::size_t face = 0;  // the face whose line is nearest
    for (std::size_t f = 1; f < 4; ++f)
      if (std::abs(out[f]) < std::abs(out[face])) face = f;
    if (std::abs(out[face]) <= o.max_offset) bins[face][std::lround(std::floor((p.z() - bottom) / o.bin))].push_back(out[face]);
  }
  std::vector<std::vector<Bin>> profiles;
  for (auto& face : bins) {
    std::vector<Bin> profile;
    for (auto& [k, v] : face)
      if (v.size() >= o.min_bin_points) profile.push_back({bottom + (static_cast<double>(k) + 0.5) * o.bin, median(std::move(v))});
    profiles.push_back(std::move(profile));
  }
  return profiles;
}

// `n` bins from `i` that agree with their median within the tolerance; their median.
std::optional<double> steady(const std::vector<Bin>& profile, std::size_t i, int n, double tolerance) {
  if (i + static_cast<std::size_t>(n) > profile.size()) return std::nullopt;
  std::vector<double> v;
  for (std::size_t k = i; k < i + static_cast<std::size_t>(n); ++k) v.push_back(profile[k].level);
  const double m = median(v);
  for (double x : v)
    if (std::abs(x - m) > tolerance) return std::nullopt;
  return m;
}

// Runs of steady bins, from the top down. A bin off its run's level starts a new run when
// it and the bins after it are steady at a level a step away; otherwise it is left out (the
// lower box's visible top edge at the interface, a stray bin).
std::vector<Run> runs(const std::vector<Bin>& profile, const SideStepOptions& o) {
  std::vector<Run> out;
  const auto start = [&](std::size_t i) {
    Run r;
    r.highest_z = profile[i].z;
    for (std::size_t k = i; k < i + static_cast<std::size_t>(o.min_run_bins); ++k) r.levels.push_back(profile[k].level);
    r.lowest_z = profile[i + static_cast<std::size_t>(o.min_run_bins) - 1].z;
    out.push_back(std::move(r));
    return i + static_cast<std::size_t>(o.min_run_bins);
  };
  std::size_t i = 0;
  while (i < profile.size() && !steady(profile, i, o.min_run_bins, o.tolerance)) ++i;
  if (i == profile.size()) return out;
  i = start(i);
  while (i < profile.size()) {
    Run& run = out.back();
    const double level = run.level(o.level_bins);
    if (std::abs(profile[i].level - level) <= o.tolerance) {
      run.levels.push_back(profile[i].level);
      run.lowest_z = profile[i].z;
      ++i;
      continue;
    }
    const std::optional<double> next = steady(profile, i, o.min_run_bins, o.tolerance);
    if (next && std::abs(*next - level) >= o.min_step) {
      i = start(i);
      continue;
    }
    ++i;
  }
  return out;
}

}  // namespace

std::vector<SideStep> side_steps(const Points& points, double bottom, const SideStepOptions& o, double trim) {
  if (!o.enabled || points.empty()) return {};
  const double top = top_height(points);
  std::vector<SideStep> steps;  // from every face; one interface may show on several
  for (const std::vector<Bin>& profile : side_profiles(points, bottom, top, o, trim)) {
    const std::vector<Run> found = runs(profile, o);
    // The top run is the top box's own face, on the outline; otherwise the outline is not
    // that face's (a top cut by occlusion, a neighbour's points) and the levels say nothing.
    if (found.empty() || std::abs(median(found.front().levels)) > o.max_top_level) continue;
    for (std::size_t k = 0; k + 1 < found.size(); ++k) {
      const Run& upper = found[k];
      const Run& lower = found[k + 1];
      const double step = std::abs(median(upper.levels) - median(lower.levels));
      if (step < o.min_step || step < o.min_contrast * (mad(upper.levels) + mad(lower.levels) + o.noise_floor)) continue;
      // Between the runs' bins lie the lower box's top edge and the upper box's bottom edge.
      steps.push_back({upper.lowest_z - 0.5 * o.bin, lower.highest_z + 0.5 * o.bin});
    }
  }
  std::sort(steps.begin(), steps.end(), [](const SideStep& a, const SideStep& b) { return a.z < b.z; });
  std::vector<SideStep> distinct;  // one interface seen on several faces: the narrowest reading
  for (const SideStep& s : steps) {
    if (!distinct.empty() && s.z - distinct.back().z < o.min_run_bins * o.bin) {
      distinct.back().z = std::max(distinct.back().z, s.z);
      distinct.back().lower_top = std::min(distinct.back().lower_top, s.lower_top);
    } else {
      distinct.push_back(s);
    }
  }
  return distinct;
}

std::vector<UprightBox> fit_column(const Points& points, double bottom, const BoxFitOptions& box,
                                   const SideStepOptions& o) {
  // The box fitted to the points between `from` and `to`, its bottom at `base` (> 0: resting
  // there; 0: as fitted) and its top at `roof` (the interface above it; infinite: as fitted).
  BoxFitOptions sides_only = box;  // a box under a step: its top is hidden, its points are side faces
  sides_only.side_faces_only = true;
  const auto part = [&](double from, double to, double base, double roof) {
    Points in;
    for (const auto& p : points)
      if (p.z() > from && p.z() <= to) in.push_back(p);
    UprightBox b = fit_upright_box(in.empty() ? points : in, std::isfinite(roof) ? sides_only : box);
    double lo = b.pose.t.z() - 0.5 * b.size.z(), hi = b.pose.t.z() + 0.5 * b.size.z();
    if (base > 0.0) lo = base;
    if (std::isfinite(roof)) hi = roof;
    b.size.z() = std::max(hi - lo, box.min_size);
    b.pose.t.z() = lo + 0.5 * b.size.z();
    return b;
  };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<UprightBox> out;
  double from = bottom, base = bottom;  // a part's lowest points, and its bottom
  const std::vector<SideStep> steps = side_steps(points, bottom, o, box.footprint_trim);
  for (const SideStep& s : steps) {
    const UprightBox lower = part(from, s.lower_top, base, s.z);
    // One face seen under the step: a sliver says where a box is, not how deep it is. It is left
    // out; the box above keeps its bottom at the step (resting on something the cloud hides).
    if (std::min(lower.size.x(), lower.size.y()) >= o.min_lower_side) out.push_back(lower);
    from = s.z + o.edge_band;
    base = s.z;
  }
  if (steps.empty()) out.push_back(part(-inf, inf, bottom, inf));  // no step: the whole column
  else out.push_back(part(from, inf, base, inf));
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
