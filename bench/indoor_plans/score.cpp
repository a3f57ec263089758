#include "bench/indoor_plans/score.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace ksmc::bench::indoor_plans {

using stdlib::indoor::Point2;
using stdlib::indoor::io::WorldResult;

namespace {

std::vector<cv::Point2f> polygon(const std::array<Point2, 4>& q) {
  std::vector<cv::Point2f> p;
  for (const auto& c : q) p.emplace_back(static_cast<float>(c.x), static_cast<float>(c.y));
  if (cv::contourArea(p, true) < 0) std::reverse(p.begin(), p.end());
  return p;
}

double f1(std::size_t tp, std::size_t found, std::size_t truth) {
  if (found == 0 && truth == 0) return 1.0;
  return found + truth == 0 ? 0.0 : 2.0 * static_cast<double>(tp) / static_cast<double>(found + truth);
}

using Edge = std::pair<int, int>;
Edge edge(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// F1 of the found edges (mapped to truth ids) against the truth edges, both restricted to edges
// between matched units.
double graph_f1(const std::vector<Edge>& truth_edges, const std::vector<Edge>& found_edges,
                const std::map<int, int>& found_to_truth) {
  std::set<int> matched_truth;
  for (const auto& [f, t] : found_to_truth) matched_truth.insert(t);
  std::set<Edge> t_set, f_set;
  for (const auto& [a, b] : truth_edges) {
    if (a != b && matched_truth.count(a) != 0 && matched_truth.count(b) != 0) t_set.insert(edge(a, b));
  }
  for (const auto& [a, b] : found_edges) {
    const auto ia = found_to_truth.find(a), ib = found_to_truth.find(b);
    if (ia == found_to_truth.end() || ib == found_to_truth.end() || ia->second == ib->second) continue;
    f_set.insert(edge(ia->second, ib->second));
  }
  std::size_t tp = 0;
  for (const auto& e : f_set) tp += t_set.count(e);
  return f1(tp, f_set.size(), t_set.size());
}

std::vector<Edge> door_edges(const WorldResult& w) {
  std::vector<Edge> e;
  for (const auto& d : w.doors) {
    if (d.unit_a != 0 && d.unit_b != 0) e.push_back(edge(d.unit_a, d.unit_b));
  }
  return e;
}

}  // namespace

double quad_iou(const std::array<Point2, 4>& a, const std::array<Point2, 4>& b) {
  const auto pa = polygon(a), pb = polygon(b);
  std::vector<cv::Point2f> inter;
  const double i = std::max(0.0, static_cast<double>(cv::intersectConvexConvex(pa, pb, inter, true)));
  const double u = std::abs(cv::contourArea(pa)) + std::abs(cv::contourArea(pb)) - i;
  return u > 0.0 ? i / u : 0.0;
}

std::string canonical_type(const std::string& type) {
  std::string s;
  for (const char c : type) s.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  if (s == "corr") return "corridor";
  return s;
}

PlanScore score(const WorldResult& truth, const WorldResult& found) {
  PlanScore s;
  s.true_units = truth.units.size();
  s.found_units = found.units.size();

  // Units: greedy one-to-one by IoU, best first (ties by index, for determinism).
  std::vector<std::tuple<double, std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < truth.units.size(); ++i) {
    for (std::size_t j = 0; j < found.units.size(); ++j) {
      const double iou = quad_iou(truth.units[i].corners, found.units[j].corners);
      if (iou >= kMinIou) pairs.emplace_back(-iou, i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  std::vector<bool> t_used(truth.units.size()), f_used(found.units.size());
  std::map<int, int> found_to_truth;
  std::size_t same_type = 0;
  for (const auto& [neg_iou, i, j] : pairs) {
    if (t_used[i] || f_used[j]) continue;
    t_used[i] = f_used[j] = true;
    found_to_truth[found.units[j].id] = truth.units[i].id;
    same_type += canonical_type(truth.units[i].type) == canonical_type(found.units[j].type) ? 1 : 0;
  }
  s.matched_units = found_to_truth.size();
  const auto ratio = [](std::size_t a, std::size_t b) { return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b); };
  s.unit_precision = ratio(s.matched_units, s.found_units);
  s.unit_recall = ratio(s.matched_units, s.true_units);
  s.type_accuracy = ratio(same_type, s.matched_units);

  // Doors: greedy one-to-one by midpoint distance.
  const double tol = kDoorTolerance / truth.map.resolution;  // cells
  const auto mid = [](const auto& d) {
    return Point2{(d.segment[0].x + d.segment[1].x) / 2.0, (d.segment[0].y + d.segment[1].y) / 2.0};
  };
  std::vector<std::tuple<double, std::size_t, std::size_t>> dpairs;
  for (std::size_t i = 0; i < truth.doors.size(); ++i) {
    for (std::size_t j = 0; j < found.doors.size(); ++j) {
      const Point2 a = mid(truth.doors[i]), b = mid(found.doors[j]);
      const double d = std::hypot(a.x - b.x, a.y - b.y);
      if (d <= tol) dpairs.emplace_back(d, i, j);
    }
  }
  std::sort(dpairs.begin(), dpairs.end());
  std::vector<bool> td(truth.doors.size()), fd(found.doors.size());
  std::size_t door_tp = 0;
  for (const auto& [d, i, j] : dpairs) {
    if (td[i] || fd[j]) continue;
    td[i] = fd[j] = true;
    ++door_tp;
  }
  s.door_precision = ratio(door_tp, found.doors.size());
  s.door_recall = ratio(door_tp, truth.doors.size());
  s.door_f1 = f1(door_tp, found.doors.size(), truth.doors.size());

  s.adjacency_f1 = graph_f1(truth.adjacent, found.adjacent, found_to_truth);
  s.door_graph_f1 = graph_f1(door_edges(truth), door_edges(found), found_to_truth);
  s.topology_f1 = (s.adjacency_f1 + s.door_graph_f1) / 2.0;
  return s;
}

}  // namespace ksmc::bench::indoor_plans
