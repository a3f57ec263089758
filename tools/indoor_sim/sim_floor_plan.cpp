#include "tools/indoor_sim/sim_floor_plan.h"

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "tools/indoor_sim/truth_result.h"

namespace ksmc::tools::indoor_sim {

using stdlib::indoor::io::DoorResult;

namespace {

constexpr int kWidth = 600, kHeight = 400;
constexpr int kWall = 4;           // cells (0.2 m)
constexpr int kDoor = 18;          // cells (0.9 m)
constexpr double kRange = 160.0;   // laser range, cells (8 m)
constexpr int kRays = 1440;        // rays per scan

constexpr std::uint8_t kGtFree = 0, kGtSolid = 1;

// Portable uniform [0,1) from the raw (standardised) mt19937_64 sequence.
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

struct Rect {
  int x0, y0, x1, y1;  // wall centre lines
};

struct Door {
  int a, b;
  bool horizontal;  // in a horizontal wall (constant y)
  int at;           // y (horizontal) or x (vertical) of the wall
  int from;         // start along the wall
};

void wall_h(cv::Mat1b& gt, int y, int x0, int x1) {
  cv::rectangle(gt, cv::Point(x0 - kWall / 2, y - kWall / 2),
                cv::Point(x1 + kWall / 2 - 1, y + kWall / 2 - 1), cv::Scalar(kGtSolid), cv::FILLED);
}
void wall_v(cv::Mat1b& gt, int x, int y0, int y1) {
  cv::rectangle(gt, cv::Point(x - kWall / 2, y0 - kWall / 2),
                cv::Point(x + kWall / 2 - 1, y1 + kWall / 2 - 1), cv::Scalar(kGtSolid), cv::FILLED);
}

}  // namespace

std::string encode_pgm(const cv::Mat1b& image, double resolution) {
  std::string s = fmt::format("P5\n# CREATOR: ksmc make_example_map {:.3f} m/pix\n{} {}\n255\n",
                              resolution, image.cols, image.rows);
  for (int r = 0; r < image.rows; ++r) {
    s.append(reinterpret_cast<const char*>(image.ptr<std::uint8_t>(r)),
             static_cast<std::size_t>(image.cols));
  }
  return s;
}

SimFloorPlan make_sim_office(std::uint64_t seed) {
  const std::vector<std::pair<Rect, const char*>> units = {
      {{20, 30, 150, 170}, "room"},   {{150, 30, 260, 170}, "room"},
      {{260, 30, 400, 170}, "room"},  {{400, 30, 580, 170}, "room"},
      {{20, 170, 580, 210}, "corridor"}, {{20, 210, 300, 370}, "hall"},
      {{300, 210, 440, 370}, "room"}, {{440, 210, 580, 370}, "room"}};
  const std::vector<Door> doors = {{1, 5, true, 170, 60},  {2, 5, true, 170, 190},
                                   {3, 5, true, 170, 300}, {4, 5, true, 170, 470},
                                   {6, 5, true, 210, 80},  {6, 5, true, 210, 220},
                                   {7, 5, true, 210, 350}, {7, 8, false, 440, 300}};
  const std::vector<std::pair<int, int>> adjacent = {{1, 2}, {1, 5}, {2, 3}, {2, 5}, {3, 4}, {3, 5},
                                                     {4, 5}, {5, 6}, {5, 7}, {5, 8}, {6, 7}, {7, 8}};
  const std::vector<cv::Rect> furniture = {{30, 40, 30, 15},  {228, 100, 26, 50}, {270, 40, 60, 18},
                                           {100, 280, 30, 20}, {200, 280, 30, 20}, {400, 330, 35, 35},
                                           {500, 218, 60, 15}, {420, 60, 20, 80}};
  // Robot path: along the corridor, into every unit except unit 4 (seen only through its door).
  std::vector<cv::Point2d> views;
  for (int x = 40; x <= 560; x += 40) views.emplace_back(x, 190);
  for (const cv::Point2d p : {cv::Point2d(85, 100), cv::Point2d(205, 80), cv::Point2d(330, 110),
                              cv::Point2d(100, 250), cv::Point2d(160, 330), cv::Point2d(250, 300),
                              cv::Point2d(370, 280), cv::Point2d(510, 290)}) {
    views.push_back(p);
  }

  // Ground-truth solid map.
  cv::Mat1b gt(kHeight, kWidth, kGtFree);
  for (const auto& [r, type] : units) {
    wall_h(gt, r.y0, r.x0, r.x1);
    wall_h(gt, r.y1, r.x0, r.x1);
    wall_v(gt, r.x0, r.y0, r.y1);
    wall_v(gt, r.x1, r.y0, r.y1);
  }
  for (const auto& d : doors) {
    if (d.horizontal) {
      cv::rectangle(gt, cv::Point(d.from, d.at - kWall), cv::Point(d.from + kDoor - 1, d.at + kWall),
                    cv::Scalar(kGtFree), cv::FILLED);
    } else {
      cv::rectangle(gt, cv::Point(d.at - kWall, d.from), cv::Point(d.at + kWall, d.from + kDoor - 1),
                    cv::Scalar(kGtFree), cv::FILLED);
    }
  }
  for (const auto& f : furniture) cv::rectangle(gt, f, cv::Scalar(kGtSolid), cv::FILLED);
  // Everything outside the building is solid ground truth too (rays stop at outer walls anyway).

  // Ray-cast exploration with hit/miss counts.
  std::mt19937_64 rng(seed);
  cv::Mat1i hits(kHeight, kWidth, 0), misses(kHeight, kWidth, 0);
  for (const auto& v : views) {
    for (int k = 0; k < kRays; ++k) {
      if (uniform(rng) < 0.03) continue;  // dropped beam: no information
      const double a = 2.0 * M_PI * k / kRays + 0.002 * (uniform(rng) - 0.5);
      const double dx = std::cos(a), dy = std::sin(a);
      int last_c = -1, last_r = -1;
      for (double t = 0.0; t <= kRange; t += 0.5) {
        const int c = static_cast<int>(std::lround(v.x + t * dx));
        const int r = static_cast<int>(std::lround(v.y + t * dy));
        if (c < 0 || r < 0 || c >= kWidth || r >= kHeight) break;
        if (c == last_c && r == last_r) continue;
        last_c = c;
        last_r = r;
        if (gt(r, c) == kGtSolid) {
          // Range noise: one beam in ten ends one cell deeper, making walls ragged.
          int hc = c, hr = r;
          if (uniform(rng) < 0.1) {
            hc = static_cast<int>(std::lround(v.x + (t + 1.0) * dx));
            hr = static_cast<int>(std::lround(v.y + (t + 1.0) * dy));
            if (hc < 0 || hr < 0 || hc >= kWidth || hr >= kHeight) hc = c, hr = r;
          }
          ++hits(hr, hc);
          break;
        }
        ++misses(r, c);
      }
    }
  }

  SimFloorPlan out;
  out.resolution = 0.05;
  out.image = cv::Mat1b(kHeight, kWidth, static_cast<std::uint8_t>(205));
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) {
      const int h = hits(r, c), m = misses(r, c);
      if (h > 0 && 2 * h >= m) {
        out.image(r, c) = 0;
      } else if (m > 0) {
        // Spurious readings (people, reflections): rare isolated occupied cells in free space.
        out.image(r, c) = uniform(rng) < 0.0005 ? 0 : 254;
      }
    }
  }

  WorldResult& w = out.truth;
  w.map = truth_map_info(out.image, out.resolution, "sim_office.pgm");
  int id = 0;
  for (const auto& [r, type] : units) {
    ++id;
    w.units.push_back(axis_unit(id, type, r.x0, r.y0, r.x1, r.y1));
  }
  id = 0;
  for (const auto& d : doors) {
    DoorResult dr;
    dr.id = ++id;
    dr.unit_a = d.a;
    dr.unit_b = d.b;
    dr.segment = axis_door_segment(d.horizontal, d.at, d.from, kDoor);
    w.doors.push_back(dr);
  }
  w.adjacent = adjacent;
  return out;
}

}  // namespace ksmc::tools::indoor_sim
