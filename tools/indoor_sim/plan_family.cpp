#include "tools/indoor_sim/plan_family.h"

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "tools/indoor_sim/truth_result.h"

namespace ksmc::tools::indoor_sim {

using stdlib::indoor::io::DoorResult;

namespace {

constexpr double kRes = 0.05;                 // m per cell
constexpr int kMargin = 20;                   // unknown cells around the building
constexpr int kMinRoom = 40, kMaxRoom = 160;  // room widths along a wall, cells (2-8 m)
constexpr std::uint8_t kOut = 2, kFree = 0, kSolid = 1;

double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }
// Uniform integer in [lo, hi] (lo <= hi).
int draw(std::mt19937_64& rng, int lo, int hi) {
  return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo + 1));
}

struct Rect {
  int x0, y0, x1, y1;  // wall centre lines, cells
};
struct Unit {
  Rect r;
  const char* type;
};
struct Door {
  int a, b;         // unit ids
  bool horizontal;  // in a horizontal wall (constant y)
  int at, from, width;
};

struct Builder {
  std::mt19937_64& rng;
  int t;  // wall thickness, cells
  std::vector<Unit> units;
  std::vector<Door> doors;

  int add(const Rect& r, const char* type) {
    units.push_back({r, type});
    return static_cast<int>(units.size());
  }
  // Boundaries lo = c0 < c1 < ... < hi with gaps in [kMinRoom, kMaxRoom]; needs hi - lo >= kMinRoom.
  std::vector<int> cuts(int lo, int hi) {
    std::vector<int> c = {lo};
    int cur = lo;
    while (hi - cur > kMaxRoom) {
      cur += draw(rng, kMinRoom, std::min(kMaxRoom, hi - cur - kMinRoom));
      c.push_back(cur);
    }
    c.push_back(hi);
    return c;
  }
  // A door between units a and b in the wall at `at`, somewhere between the walls at lo and hi.
  void door(int a, int b, bool horizontal, int at, int lo, int hi) {
    const int first = lo + (t - t / 2) + 2, last = hi - t / 2 - 3;
    const int width = std::min(draw(rng, 16, 32), last - first + 1);  // 0.8-1.6 m
    doors.push_back({a, b, horizontal, at, first + draw(rng, 0, last - first + 1 - width), width});
  }
  // Rooms along the horizontal wall y = at over [lo, hi], `depth` deep above or below it, each
  // with a door to `spine`; some neighbours get a second door between them.
  void row_h(int at, int lo, int hi, int depth, bool above, int spine) {
    const std::vector<int> c = cuts(lo, hi);
    const int y0 = above ? at - depth : at, y1 = above ? at : at + depth;
    int prev = 0;
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
      const int id = add({c[i], y0, c[i + 1], y1}, "room");
      door(id, spine, true, at, c[i], c[i + 1]);
      if (prev != 0 && uniform(rng) < 0.25) door(prev, id, false, c[i], y0, y1);
      prev = id;
    }
  }
  // Rooms along the vertical wall x = at over [lo, hi], `depth` deep to its right.
  void column_right(int at, int lo, int hi, int depth, int spine) {
    const std::vector<int> c = cuts(lo, hi);
    int prev = 0;
    for (std::size_t i = 0; i + 1 < c.size(); ++i) {
      const int id = add({at, c[i], at + depth, c[i + 1]}, "room");
      door(id, spine, false, at, c[i], c[i + 1]);
      if (prev != 0 && uniform(rng) < 0.25) door(prev, id, true, c[i], at, at + depth);
      prev = id;
    }
  }
};

bool shares_wall(const Rect& a, const Rect& b) {
  const bool vx = a.x1 == b.x0 || a.x0 == b.x1, hy = a.y1 == b.y0 || a.y0 == b.y1;
  const int oy = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  const int ox = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
  return (vx && oy > 0) || (hy && ox > 0);
}

}  // namespace

PlanLayout plan_layout(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return static_cast<PlanLayout>(draw(rng, 0, 2));
}

SimFloorPlan make_plan(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto layout = static_cast<PlanLayout>(draw(rng, 0, 2));  // first draw: plan_layout
  Builder b{rng, draw(rng, 2, 6), {}, {}};                        // walls 0.1-0.3 m
  const int cw = draw(rng, 30, 50);                               // corridor 1.5-2.5 m wide
  if (layout == PlanLayout::kStraight) {
    const int len = draw(rng, 240, 600);  // 12-30 m
    const int spine = b.add({0, 0, len, cw}, "corridor");
    b.row_h(0, 0, len, draw(rng, 60, 140), true, spine);
    b.row_h(cw, 0, len, draw(rng, 60, 140), false, spine);
  } else if (layout == PlanLayout::kHall) {
    const int len = draw(rng, 160, 400), depth = draw(rng, 100, 180);  // 8-20 x 5-9 m
    const int hall = b.add({0, 0, len, depth}, "hall");
    b.row_h(0, 0, len, draw(rng, 60, 140), true, hall);
    if (uniform(rng) < 0.5) b.row_h(depth, 0, len, draw(rng, 60, 140), false, hall);
  } else {
    const int len = draw(rng, 240, 500), down = draw(rng, 120, 280);  // legs 12-25 m, 6-14 m
    const int h = b.add({0, 0, len, cw}, "corridor");
    const int v = b.add({0, cw, cw, cw + down}, "corridor");
    // The legs meet in an opening between the vertical leg's side walls.
    const int open0 = b.t - b.t / 2, open1 = cw - b.t / 2 - 1;  // inner cells of the leg
    b.doors.push_back({h, v, true, cw, open0, open1 - open0 + 1});
    b.row_h(0, 0, len, draw(rng, 60, 140), true, h);
    const int depth = draw(rng, 60, 140);
    b.column_right(cw, cw, cw + down, depth, v);
    if (len - (cw + depth) >= kMinRoom && uniform(rng) < 0.6) {
      b.row_h(cw, cw + depth, len, draw(rng, 60, 140), false, h);
    }
  }

  // Shift into the image with a margin of unknown cells.
  int minx = 1 << 30, miny = 1 << 30, maxx = -(1 << 30), maxy = -(1 << 30);
  for (const auto& u : b.units) {
    minx = std::min(minx, u.r.x0), miny = std::min(miny, u.r.y0);
    maxx = std::max(maxx, u.r.x1), maxy = std::max(maxy, u.r.y1);
  }
  const int dx = kMargin - minx, dy = kMargin - miny;
  for (auto& u : b.units) u.r = {u.r.x0 + dx, u.r.y0 + dy, u.r.x1 + dx, u.r.y1 + dy};
  for (auto& d : b.doors) {
    d.at += d.horizontal ? dy : dx;
    d.from += d.horizontal ? dx : dy;
  }
  const int width = maxx - minx + 2 * kMargin, height = maxy - miny + 2 * kMargin;

  // Ground truth: outside, free inside units, walls, door ways, furniture.
  const int t = b.t, lo = t / 2, hi = t - t / 2 - 1;  // a wall at c covers [c - lo, c + hi]
  cv::Mat1b gt(height, width, kOut);
  for (const auto& u : b.units) {
    cv::rectangle(gt, cv::Point(u.r.x0, u.r.y0), cv::Point(u.r.x1, u.r.y1), cv::Scalar(kFree), cv::FILLED);
  }
  for (const auto& u : b.units) {
    const Rect& r = u.r;
    const cv::Scalar s(kSolid);
    cv::rectangle(gt, cv::Point(r.x0 - lo, r.y0 - lo), cv::Point(r.x1 + hi, r.y0 + hi), s, cv::FILLED);
    cv::rectangle(gt, cv::Point(r.x0 - lo, r.y1 - lo), cv::Point(r.x1 + hi, r.y1 + hi), s, cv::FILLED);
    cv::rectangle(gt, cv::Point(r.x0 - lo, r.y0 - lo), cv::Point(r.x0 + hi, r.y1 + hi), s, cv::FILLED);
    cv::rectangle(gt, cv::Point(r.x1 - lo, r.y0 - lo), cv::Point(r.x1 + hi, r.y1 + hi), s, cv::FILLED);
  }
  for (const auto& d : b.doors) {
    const int e = d.from + d.width - 1;
    if (d.horizontal) {
      cv::rectangle(gt, cv::Point(d.from, d.at - t), cv::Point(e, d.at + t), cv::Scalar(kFree), cv::FILLED);
    } else {
      cv::rectangle(gt, cv::Point(d.at - t, d.from), cv::Point(d.at + t, e), cv::Scalar(kFree), cv::FILLED);
    }
  }
  for (const auto& u : b.units) {
    if (std::string(u.type) != "room" || uniform(rng) >= 0.5) continue;
    const int n = draw(rng, 1, 2);
    for (int k = 0; k < n; ++k) {
      const int w = draw(rng, 8, 24), h = draw(rng, 8, 24), m = 14;  // 0.4-1.2 m, 0.7 m off walls
      if (u.r.x1 - u.r.x0 - 2 * m - w < 0 || u.r.y1 - u.r.y0 - 2 * m - h < 0) continue;
      const int x = draw(rng, u.r.x0 + m, u.r.x1 - m - w), y = draw(rng, u.r.y0 + m, u.r.y1 - m - h);
      cv::rectangle(gt, cv::Rect(x, y, w, h), cv::Scalar(kSolid), cv::FILLED);
    }
  }

  // The map: unknown outside; ragged walls, isolated spurious hits and unseen cells in free space.
  SimFloorPlan out;
  out.resolution = kRes;
  out.image = cv::Mat1b(height, width, static_cast<std::uint8_t>(205));
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      if (gt(r, c) == kSolid) {
        out.image(r, c) = 0;
      } else if (gt(r, c) == kFree) {
        const bool by_wall = (r > 0 && gt(r - 1, c) == kSolid) || (r + 1 < height && gt(r + 1, c) == kSolid) ||
                             (c > 0 && gt(r, c - 1) == kSolid) || (c + 1 < width && gt(r, c + 1) == kSolid);
        const double p = uniform(rng);
        out.image(r, c) = (by_wall && p < 0.08) || p < 0.001 ? 0 : (p > 0.997 ? 205 : 254);
      }
    }
  }

  WorldResult& w = out.truth;
  w.map = truth_map_info(out.image, kRes, "plan.pgm");
  for (std::size_t i = 0; i < b.units.size(); ++i) {
    const Rect& r = b.units[i].r;
    const int id = static_cast<int>(i) + 1;
    w.units.push_back(axis_unit(id, b.units[i].type, r.x0, r.y0, r.x1, r.y1));
    for (std::size_t j = 0; j < i; ++j) {
      if (shares_wall(b.units[j].r, r)) w.adjacent.emplace_back(static_cast<int>(j) + 1, id);
    }
  }
  std::sort(w.adjacent.begin(), w.adjacent.end());
  for (std::size_t i = 0; i < b.doors.size(); ++i) {
    const Door& d = b.doors[i];
    DoorResult dr;
    dr.id = static_cast<int>(i) + 1;
    dr.unit_a = std::min(d.a, d.b);
    dr.unit_b = std::max(d.a, d.b);
    dr.segment = axis_door_segment(d.horizontal, d.at, d.from, d.width);
    w.doors.push_back(dr);
  }
  return out;
}

}  // namespace ksmc::tools::indoor_sim
