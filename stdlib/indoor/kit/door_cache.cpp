#include "stdlib/indoor/kit/door_cache.h"

#include <algorithm>
#include <cmath>

#include "stdlib/indoor/detect/hough.h"

namespace ksmc::stdlib::indoor::kit {

namespace {

struct Box {
  double x0, y0, x1, y1;
};

// Axis-aligned box of the rectangle's corners, grown by `margin` cells.
Box box_of(const OrientedRect& r, double margin) {
  Box b{1e300, 1e300, -1e300, -1e300};
  for (const Point2& c : r.corners()) {
    b.x0 = std::min(b.x0, c.x);
    b.y0 = std::min(b.y0, c.y);
    b.x1 = std::max(b.x1, c.x);
    b.y1 = std::max(b.y1, c.y);
  }
  return {b.x0 - margin, b.y0 - margin, b.x1 + margin, b.y1 + margin};
}

bool meet(const Box& a, const Box& b) { return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1; }

}  // namespace

std::vector<CandidateDoor> DoorCandidateCache::candidates(const ClassGrid& grid, const std::vector<OrientedRect>& units) {
  std::vector<CandidateDoor> out;
  if (units.size() < 2) return out;
  if (!checked_ || checked_grid_ != grid.data) {  // validate the grid once, not once per pair
    detect::check_class_grid(grid, "detect_doors");
    checked_ = true;
    checked_grid_ = grid.data;
  }
  // A wall band reaches `expand` cells off its wall, and its pixel box one or two cells more
  // (rounding); two units whose boxes grown by that much do not meet have no overlapping bands.
  const double margin = std::max(params_.expand, 0.0) + 3.0;
  std::vector<Box> boxes;
  boxes.reserve(units.size());
  for (const auto& u : units) boxes.push_back(box_of(u, margin));
  if (pairs_.size() > max_pairs_) pairs_.clear();
  for (std::size_t i = 0; i < units.size(); ++i)
    for (std::size_t j = i + 1; j < units.size(); ++j) {
      if (!meet(boxes[i], boxes[j])) continue;
      const OrientedRect& a = units[i];
      const OrientedRect& b = units[j];
      const Key key{a.cx, a.cy, a.w, a.h, a.theta, b.cx, b.cy, b.w, b.h, b.theta};
      auto it = pairs_.find(key);
      if (it == pairs_.end()) {
        ++calls_;
        it = pairs_.emplace(key, to_door_candidates(detect::detect_doors(grid, {a, b}, params_, detect::GridCheck::Trusted))).first;
      }
      out.insert(out.end(), it->second.begin(), it->second.end());
    }
  return out;
}

}  // namespace ksmc::stdlib::indoor::kit
