#include "stdlib/indoor/io/world_obj.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/map_frame.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

namespace {

using Interval = std::pair<double, double>;

// [0, length] minus the door intervals (sorted, merged).
std::vector<Interval> wall_pieces(double length, std::vector<Interval> doors) {
  std::sort(doors.begin(), doors.end());
  std::vector<Interval> out;
  double at = 0.0;
  for (const auto& [a, b] : doors) {
    if (a > at) out.emplace_back(at, std::min(a, length));
    at = std::max(at, b);
    if (at >= length) break;
  }
  if (at < length) out.emplace_back(at, length);
  out.erase(std::remove_if(out.begin(), out.end(), [](const Interval& i) { return i.second - i.first < 1e-6; }), out.end());
  return out;
}

}  // namespace

std::string world_obj_text(const WorldResult& w, double height) {
  validate_world(w, false);
  const MapFrame frame = frame_of(w.map);
  const double th = w.wall_thickness;
  std::string out = "# ksmc indoor world: unit walls extruded, door gaps; metres, map frame, z up\n";
  out += fmt::format("# map {} ({} x {} cells, {} m per cell), wall height {} m, wall thickness {} cells\n", w.map.source,
                     w.map.width, w.map.height, w.map.resolution, height, th);
  out += "o walls\n";
  int next_vertex = 1;
  for (const auto& u : w.units) {
    const auto& q = u.corners;
    if (!finite_quad(q)) continue;
    const double area2 = signed_area2(q);
    if (area2 == 0.0) continue;
    const double inward = area2 > 0.0 ? 1.0 : -1.0;  // image y down: left of the edge is inside for area2 > 0
    int piece_no = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      const Point2 a = q[k], b = q[(k + 1) % 4];
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      if (!(len > 0.0)) continue;
      const Point2 dir{(b.x - a.x) / len, (b.y - a.y) / len};
      const Point2 nrm{-dir.y * inward, dir.x * inward};
      std::vector<Interval> gaps;
      std::vector<int> gap_doors;
      for (const auto& d : w.doors) {
        double t[2], off[2];
        for (int e = 0; e < 2; ++e) {
          const double rx = d.segment[e].x - a.x, ry = d.segment[e].y - a.y;
          t[e] = rx * dir.x + ry * dir.y;
          off[e] = std::fabs(rx * nrm.x + ry * nrm.y);
        }
        const double tol = std::max(2.0 * th, 1.0);
        if (off[0] > tol || off[1] > tol) continue;
        const double lo = std::max(0.0, std::min(t[0], t[1])), hi = std::min(len, std::max(t[0], t[1]));
        if (hi > lo) {
          gaps.emplace_back(lo, hi);
          gap_doors.push_back(d.id);
        }
      }
      for (const int id : gap_doors) out += fmt::format("# door {} cuts unit {} edge {}\n", id, u.id, k);
      for (const auto& [t0, t1] : wall_pieces(len, gaps)) {
        const Point2 base[4] = {{a.x + dir.x * t0, a.y + dir.y * t0},
                                {a.x + dir.x * t1, a.y + dir.y * t1},
                                {a.x + dir.x * t1 + nrm.x * th, a.y + dir.y * t1 + nrm.y * th},
                                {a.x + dir.x * t0 + nrm.x * th, a.y + dir.y * t0 + nrm.y * th}};
        Point2 m[4];
        for (int i = 0; i < 4; ++i) m[i] = frame.to_metres(base[i]);
        // The metric quad's orientation (y up flips it, a yaw does not): faces wound outwards.
        double sa = 0.0;
        for (int i = 0; i < 4; ++i) sa += m[i].x * m[(i + 1) % 4].y - m[(i + 1) % 4].x * m[i].y;
        if (sa < 0.0) std::swap(m[1], m[3]);
        out += fmt::format("g u{}_wall{}\n", u.id, piece_no++);
        for (const double z : {0.0, height})
          for (const auto& p : m) out += fmt::format("v {:.4f} {:.4f} {:.4f}\n", p.x, p.y, z);
        const int v = next_vertex;  // bottom v..v+3 (counter-clockwise from above), top v+4..v+7
        out += fmt::format("f {} {} {} {}\n", v, v + 3, v + 2, v + 1);      // floor side, facing down
        out += fmt::format("f {} {} {} {}\n", v + 4, v + 5, v + 6, v + 7);  // top, facing up
        for (int i = 0; i < 4; ++i) {
          const int j = (i + 1) % 4;
          out += fmt::format("f {} {} {} {}\n", v + i, v + j, v + 4 + j, v + 4 + i);
        }
        next_vertex += 8;
      }
    }
  }
  return out;
}

void write_world_obj(const std::filesystem::path& path, const WorldResult& w, double height) {
  runtime::io::write_file_atomic(path, world_obj_text(w, height));
}

}  // namespace ksmc::stdlib::indoor::io
