#include "stdlib/segments/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ksmc::stdlib::segments {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

Scene::Scene(std::shared_ptr<const std::vector<Vec2>> points, LikelihoodParams params)
    : points_(std::move(points)), params_(params) {
  if (!points_) throw std::invalid_argument("segments scene: no points");
  if (!(params_.sigma > 0.0) || !std::isfinite(params_.sigma))
    throw std::invalid_argument("points.gaussian: sigma must be positive");
  if (!(params_.background > 0.0 && params_.background < 1.0))
    throw std::invalid_argument("points.gaussian: background must be in (0, 1)");
  inv_two_sigma2_ = 1.0 / (2.0 * params_.sigma * params_.sigma);
  log_bg_ = std::log(params_.background);
  full_assign();
}

double Scene::term(double d) const {
  if (!std::isfinite(d)) return log_bg_;
  return std::log((1.0 - params_.background) * std::exp(-d * d * inv_two_sigma2_) + params_.background);
}

void Scene::full_assign() {
  const std::size_t n = points_->size();
  nearest_.assign(n, -1);
  dist_.assign(n, kInf);
  terms_.assign(n, 0.0);
  total_ = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      const double d = point_segment_distance((*points_)[i], lines_[k].seg);
      if (d < dist_[i]) {
        dist_[i] = d;
        nearest_[i] = static_cast<int>(k);
      }
    }
    terms_[i] = term(dist_[i]);
    total_ += terms_[i];
  }
}

double Scene::recompute_log_likelihood() const {
  double s = 0.0;
  for (const Vec2& p : *points_) {
    double best = kInf;
    for (const Line& l : lines_) best = std::min(best, point_segment_distance(p, l.seg));
    s += term(best);
  }
  return s;
}

std::vector<std::size_t> Scene::change(std::span<const std::size_t> remove, std::span<const Segment> add,
                                      std::span<const std::uint64_t> ids) {
  if (pending_) throw std::logic_error("segments scene: change while another is pending");
  backup_.lines = lines_;
  backup_.nearest = nearest_;
  backup_.dist = dist_;
  backup_.terms = terms_;
  backup_.total = total_;
  backup_.next_id = next_id_;
  pending_ = true;

  // Old index -> new index (-1: removed).
  std::vector<int> map(lines_.size(), 0);
  for (const std::size_t r : remove) {
    if (r >= lines_.size() || map[r] < 0) throw std::logic_error("segments scene: bad or repeated removal index");
    map[r] = -1;
  }
  std::vector<Line> kept;
  kept.reserve(lines_.size() - remove.size() + add.size());
  for (std::size_t k = 0; k < lines_.size(); ++k)
    if (map[k] >= 0) {
      map[k] = static_cast<int>(kept.size());
      kept.push_back(lines_[k]);
    }
  const std::size_t first_added = kept.size();
  std::vector<std::size_t> added;
  for (std::size_t k = 0; k < add.size(); ++k) {
    added.push_back(kept.size());
    const std::uint64_t id = ids.empty() ? next_id_++ : ids[k];
    kept.push_back({canonical(add[k].a, add[k].b), id});
  }
  lines_ = std::move(kept);

  double delta = 0.0;
  const std::size_t n = points_->size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = (*points_)[i];
    const int old = nearest_[i];
    bool changed = false;
    if (old >= 0 && map[static_cast<std::size_t>(old)] < 0) {
      // Its nearest line is gone: search all remaining lines.
      nearest_[i] = -1;
      dist_[i] = kInf;
      for (std::size_t k = 0; k < lines_.size(); ++k) {
        const double d = point_segment_distance(p, lines_[k].seg);
        if (d < dist_[i]) {
          dist_[i] = d;
          nearest_[i] = static_cast<int>(k);
        }
      }
      changed = true;
    } else {
      if (old >= 0) nearest_[i] = map[static_cast<std::size_t>(old)];
      for (std::size_t k = first_added; k < lines_.size(); ++k) {
        const double d = point_segment_distance(p, lines_[k].seg);
        if (d < dist_[i]) {
          dist_[i] = d;
          nearest_[i] = static_cast<int>(k);
          changed = true;
        }
      }
    }
    if (changed) {
      const double t = term(dist_[i]);
      delta += t - terms_[i];
      terms_[i] = t;
    }
  }
  total_ += delta;
  return added;
}

void Scene::commit() {
  pending_ = false;
}

void Scene::rollback() {
  if (!pending_) return;
  lines_.swap(backup_.lines);
  nearest_.swap(backup_.nearest);
  dist_.swap(backup_.dist);
  terms_.swap(backup_.terms);
  total_ = backup_.total;
  next_id_ = backup_.next_id;
  pending_ = false;
}

void Scene::reset(std::vector<Line> lines, std::uint64_t next_id) {
  pending_ = false;
  lines_ = std::move(lines);
  for (Line& l : lines_) l.seg = canonical(l.seg.a, l.seg.b);
  next_id_ = next_id;
  for (const Line& l : lines_) next_id_ = std::max(next_id_, l.id + 1);
  full_assign();
}

}  // namespace ksmc::stdlib::segments
