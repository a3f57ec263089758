// Clusters split by a resting box's shadow (shadow_merge.h): the far part of a top that a
// box lying across it hides from the sensor is joined to the near part; a top seen from
// overhead, a far part with something on it, a tall box's side face crossing the plane's
// height, and (with the cloud's rays) a neighbour with the table seen between are not.
#include <catch2/catch.hpp>

#include "stdlib/tabletop/perception/shadow_merge.h"

using namespace ksmc::stdlib::tabletop::perception;
using ksmc::stdlib::tabletop::FreeSpace;
using ksmc::stdlib::tabletop::RayIndex;

namespace {

void add_top(Points& pts, double x0, double x1, double y0, double y1, double z) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.003)
    for (double y = y0; y <= y1 + 1e-9; y += 0.003) pts.emplace_back(x, y, z);
}
// A vertical face at y = y0 facing -y.
void add_face(Points& pts, double x0, double x1, double y0, double z0, double z1) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.003)
    for (double z = z0; z <= z1 + 1e-9; z += 0.003) pts.emplace_back(x, y0, z);
}

// The near part of a lower box's top (z = 6 cm) with a box lying across it (4 cm high,
// y from -1 to 3 cm).
Points near_part() {
  Points a;
  add_top(a, -0.1, 0.1, -0.07, -0.013, 0.06);
  add_face(a, -0.1, 0.1, -0.01, 0.063, 0.1);
  add_top(a, -0.1, 0.1, -0.01, 0.03, 0.1);
  return a;
}
// The far part of the lower box's top, beyond the shadow (which, from the low sensor, ends
// at y = 12.8 cm).
Points far_part() {
  Points b;
  add_top(b, -0.1, 0.1, 0.135, 0.2, 0.06);
  return b;
}

const Eigen::Vector3d kLow(0.0, -1.0, 0.5);

}  // namespace

TEST_CASE("shadow merge: the far part of a top behind a box lying across it is joined", "[perception][shadow]") {
  const Points a = near_part(), b = far_part();
  const auto merged = merge_shadow_split({a, b}, kLow);
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].size() == a.size() + b.size());
  ShadowMergeOptions off;
  off.enabled = false;
  CHECK(merge_shadow_split({a, b}, kLow, off).size() == 2);
}

TEST_CASE("shadow merge: what is not a shadow split stays apart", "[perception][shadow]") {
  const Points a = near_part(), b = far_part();
  // Seen from overhead the box's shadow ends at its own far side: the gap was seen.
  CHECK(merge_shadow_split({a, b}, Eigen::Vector3d(0.0, 0.0, 1.0)).size() == 2);
  // Something stands on the far part: it is not a bare top.
  Points covered = b;
  add_top(covered, -0.02, 0.02, 0.16, 0.18, 0.09);
  CHECK(merge_shadow_split({a, covered}, kLow).size() == 2);
  // A tall box (20 cm) whose near face crosses 6 cm: a face is not a top.
  Points tall;
  add_face(tall, -0.05, 0.05, -0.05, 0.0, 0.2);
  add_top(tall, -0.05, 0.05, -0.05, 0.0, 0.2);
  CHECK(merge_shadow_split({tall, b}, kLow).size() == 2);
}

namespace {

struct Block {  // an axis-aligned box
  Eigen::Vector3d lo, hi;
};

// Whether the segment from p to the sensor passes through a block (slab test, its own
// surface left out).
bool hidden(const Eigen::Vector3d& p, const Eigen::Vector3d& sensor, const std::vector<Block>& blocks) {
  const Eigen::Vector3d d = sensor - p;
  for (const Block& b : blocks) {
    double t0 = 1e-6, t1 = 1.0;
    for (int k = 0; k < 3 && t0 <= t1; ++k) {
      if (std::abs(d[k]) < 1e-12) {
        if (p[k] <= b.lo[k] || p[k] >= b.hi[k]) t1 = -1.0;
        continue;
      }
      const double a = (b.lo[k] - p[k]) / d[k], c = (b.hi[k] - p[k]) / d[k];
      t0 = std::max(t0, std::min(a, c));
      t1 = std::min(t1, std::max(a, c));
    }
    if (t0 < t1 - 1e-9) return true;
  }
  return false;
}

// The points of a block's top and side faces (3 mm grid) that the sensor sees.
Points seen_faces(const Block& b, const Eigen::Vector3d& sensor, const std::vector<Block>& all) {
  Points candidates;
  add_top(candidates, b.lo.x(), b.hi.x(), b.lo.y(), b.hi.y(), b.hi.z());
  for (double z = b.lo.z() + 0.0015; z < b.hi.z(); z += 0.003) {
    for (double x = b.lo.x(); x <= b.hi.x() + 1e-9; x += 0.003) {
      candidates.emplace_back(x, b.lo.y(), z);
      candidates.emplace_back(x, b.hi.y(), z);
    }
    for (double y = b.lo.y(); y <= b.hi.y() + 1e-9; y += 0.003) {
      candidates.emplace_back(b.lo.x(), y, z);
      candidates.emplace_back(b.hi.x(), y, z);
    }
  }
  Points seen;
  for (const auto& p : candidates)
    if (!hidden(p, sensor, all)) seen.push_back(p);
  return seen;
}

// The whole cloud: the blocks' seen faces and the table's seen points.
RayIndex seen_cloud(const std::vector<Block>& blocks, const Eigen::Vector3d& sensor) {
  FreeSpace fs;
  fs.sensor = sensor;
  for (const Block& b : blocks) {
    const Points f = seen_faces(b, sensor, blocks);
    fs.points.insert(fs.points.end(), f.begin(), f.end());
  }
  for (double x = -0.4; x <= 0.5; x += 0.003)
    for (double y = -0.4; y <= 0.5; y += 0.003)
      if (!hidden({x, y, 0.0}, sensor, blocks)) fs.points.emplace_back(x, y, 0.0);
  return RayIndex(std::move(fs));
}

const Eigen::Vector3d kHigh(0.0, -0.3, 1.0);
const Block kAcross{{-0.1, -0.01, 0.06}, {0.1, 0.03, 0.1}};  // a box lying across the lower top

}  // namespace

TEST_CASE("shadow merge: a neighbour of the same height with the table seen between is not the far part",
          "[perception][shadow]") {
  // Box a (6 cm) ends just past the box lying across it; box b (6 cm) starts beyond that box's
  // shadow and reaches 20 cm further along x, so the table is seen inside the hull of the two tops.
  const Block a{{-0.1, -0.1, 0.0}, {0.1, 0.035, 0.06}}, b{{-0.1, 0.05, 0.0}, {0.3, 0.2, 0.06}};
  const std::vector<Block> blocks{a, kAcross, b};
  Points near = seen_faces(a, kHigh, blocks);
  const Points across = seen_faces(kAcross, kHigh, blocks);
  near.insert(near.end(), across.begin(), across.end());
  const Points far = seen_faces(b, kHigh, blocks);
  // The shadow test alone takes b for the far part of a's top.
  REQUIRE(merge_shadow_split({near, far}, kHigh).size() == 1);
  const RayIndex rays = seen_cloud(blocks, kHigh);
  CHECK(merge_shadow_split({near, far}, kHigh, {}, &rays).size() == 2);
  // One long box under the one lying across it: the rays end on its top, so it is joined.
  const Block whole{{-0.1, -0.1, 0.0}, {0.1, 0.2, 0.06}};
  const std::vector<Block> one{whole, kAcross};
  Points top_near, top_far;
  for (const auto& p : seen_faces(whole, kHigh, one)) (p.y() < 0.0 ? top_near : top_far).push_back(p);
  top_near.insert(top_near.end(), across.begin(), across.end());
  const RayIndex one_rays = seen_cloud(one, kHigh);
  CHECK(merge_shadow_split({top_near, top_far}, kHigh, {}, &one_rays).size() == 1);
}
