#include "tools/tabletop_sim/layout.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ksmc::tools::tabletop_sim {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDropGap = 0.003;  // m between a box and what it is dropped onto

// Rotation that makes local axis `axis` vertical.
Eigen::Quaterniond axis_up(int axis) {
  if (axis == 0) return Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()));
  if (axis == 1) return Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()));
  return Eigen::Quaterniond::Identity();
}

int smallest_axis(const Eigen::Vector3d& s) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (s[i] < s[k]) k = i;
  }
  return k;
}

int largest_axis(const Eigen::Vector3d& s) {
  int k = 0;
  for (int i = 1; i < 3; ++i) {
    if (s[i] > s[k]) k = i;
  }
  return k;
}

// Upright box footprint: centre, half extents along its horizontal axes, yaw of the first one.
struct Footprint {
  Eigen::Vector2d centre;
  Eigen::Vector2d half;
  double yaw = 0.0;
};

Footprint footprint(const Box& b) {
  const Eigen::Matrix3d r = b.pose.rotation();
  const int up = vertical_axis(b.pose.q);
  const int a = (up + 1) % 3;
  const int c = (up + 2) % 3;
  Footprint f;
  f.centre = b.pose.t.head<2>();
  f.half = Eigen::Vector2d(0.5 * b.size[a], 0.5 * b.size[c]);
  f.yaw = std::atan2(r(1, a), r(0, a));
  return f;
}

bool overlaps_any(const Footprint& f, const std::vector<Footprint>& placed, double clearance) {
  return std::any_of(placed.begin(), placed.end(), [&](const Footprint& g) {
    return footprints_overlap(f.centre, f.half, f.yaw, g.centre, g.half, g.yaw, clearance);
  });
}

// Centre inside the drop region, whole footprint at least 5 cm inside the table edge.
bool inside_region(const Footprint& f, const Eigen::Vector2d& region, const TableSpec& table) {
  const double rx = std::abs(std::cos(f.yaw)) * f.half.x() + std::abs(std::sin(f.yaw)) * f.half.y();
  const double ry = std::abs(std::sin(f.yaw)) * f.half.x() + std::abs(std::cos(f.yaw)) * f.half.y();
  return std::abs(f.centre.x()) <= region.x() && std::abs(f.centre.y()) <= region.y() &&
         std::abs(f.centre.x()) + rx <= table.half_extent.x() - 0.05 &&
         std::abs(f.centre.y()) + ry <= table.half_extent.y() - 0.05;
}

// Orientation for a box resting on a face, with a random yaw and a small natural tilt.
Eigen::Quaterniond resting_orientation(Rng& rng, int up_axis, double yaw) {
  const double tilt = rng.uniform(0.0, 1.5) * kPi / 180.0;
  return (random_tilt(rng, tilt) * yaw_rotation(yaw) * axis_up(up_axis)).normalized();
}

// Lowers/raises the box so that its lowest point is at `z`.
void set_bottom(Box& b, double z) { b.pose.t.z() += z - lowest_z(b); }

// True when `b` comes within 3 mm of a body already placed.
bool clashes(const Box& b, const std::vector<SimBody>& bodies) {
  return std::any_of(bodies.begin(), bodies.end(), [&](const SimBody& o) { return sat_overlap(b, o.box) > -0.003; });
}

// Tries to drop `item` leaning against the bottom box of a column. Returns false if no free spot.
bool place_leaner(Rng& rng, const BoxItem& item, const Box& base, const std::vector<SimBody>& bodies,
                  const Eigen::Vector2d& region, Box& out) {
  const Footprint fb = footprint(base);
  for (int attempt = 0; attempt < 8; ++attempt) {
    const int side = rng.uniform_int(0, 3);
    const double side_yaw = fb.yaw + side * kPi / 2;
    const Eigen::Vector2d n(std::cos(side_yaw), std::sin(side_yaw));
    const double base_reach = (side % 2 == 0) ? fb.half.x() : fb.half.y();
    // Tallest axis up, thinnest axis facing the column.
    const int up = largest_axis(item.size);
    const int thin = smallest_axis(item.size);
    if (thin == up) return false;
    Box b;
    b.size = item.size;
    // Local `thin` axis must point along n: after axis_up(up), find the yaw that does that.
    Eigen::Quaterniond q = axis_up(up);
    const Eigen::Vector3d thin_dir = q * Eigen::Vector3d::Unit(thin);
    const double thin_yaw = std::atan2(thin_dir.y(), thin_dir.x());
    q = yaw_rotation(side_yaw - thin_yaw) * q;
    const double alpha = rng.uniform(15.0, 30.0) * kPi / 180.0;
    const Eigen::Vector3d upv(-n.x() * std::sin(alpha), -n.y() * std::sin(alpha), std::cos(alpha));
    q = (Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), upv) * q).normalized();
    b.pose.q = q;
    // Horizontal reach of the tilted box along n, measured from its centre at the bottom.
    const Eigen::Matrix3d r = b.pose.rotation();
    double reach = 0.0;
    for (int i = 0; i < 3; ++i) reach += std::abs(r.col(i).head<2>().dot(n)) * 0.5 * b.size[i];
    const double dist = base_reach + reach + 0.004;
    b.pose.t.head<2>() = fb.centre + dist * n + rng.uniform(-0.3, 0.3) * std::min(fb.half.x(), fb.half.y()) *
                                                     Eigen::Vector2d(-n.y(), n.x());
    b.pose.t.z() = 0.0;
    set_bottom(b, 0.002);
    if (std::abs(b.pose.t.x()) > region.x() || std::abs(b.pose.t.y()) > region.y() || clashes(b, bodies)) continue;
    out = b;
    return true;
  }
  return false;
}

// Tries to drop `item`, lying flat, on the top face of `base`, at the end of its long axis
// away from `upper` (the box already on it), so that `base` carries both.
bool place_beside(Rng& rng, const BoxItem& item, const Box& base, const Box& upper, const std::vector<SimBody>& bodies,
                  Box& out) {
  const Footprint fb = footprint(base);
  const int long_axis = fb.half.x() >= fb.half.y() ? 0 : 1;
  const Eigen::Vector2d u = Eigen::Rotation2Dd(fb.yaw) * Eigen::Vector2d::Unit(long_axis);
  const double side = (upper.pose.t.head<2>() - fb.centre).dot(u) > 0.0 ? -1.0 : 1.0;
  for (int attempt = 0; attempt < 12; ++attempt) {
    Box b;
    b.size = item.size;
    const double yaw = fb.yaw + (rng.bernoulli(0.5) ? 0.0 : kPi / 2) + rng.uniform(-0.1, 0.1);
    b.pose.q = resting_orientation(rng, smallest_axis(item.size), yaw);
    const Footprint f = footprint(b);
    // Half extent of the new box along u.
    const double reach = std::abs(std::cos(f.yaw - std::atan2(u.y(), u.x()))) * f.half.x() +
                         std::abs(std::sin(f.yaw - std::atan2(u.y(), u.x()))) * f.half.y();
    if (reach > 0.8 * fb.half[long_axis]) continue;  // would hang over the centre
    const Eigen::Vector2d c = fb.centre + side * (fb.half[long_axis] - reach) * u;
    b.pose.t = Eigen::Vector3d(c.x(), c.y(), 0.0);
    set_bottom(b, highest_z(base) + kDropGap);
    if (clashes(b, bodies)) continue;
    out = b;
    return true;
  }
  return false;
}

}  // namespace

Eigen::Vector2d drop_region(int n, const TableSpec& table, double spread) {
  const double hx = std::min({spread * (0.16 + 0.01 * n), spread * 0.34, table.half_extent.x() - 0.08});
  const double hy = std::min({spread * (0.12 + 0.007 * n), spread * 0.25, table.half_extent.y() - 0.08});
  return {hx, hy};
}

std::optional<Layout> draw_layout(Rng& rng, int n, const TableSpec& table, const LayoutParams& params,
                                  double spread) {
  Layout layout;
  layout.region_half = drop_region(n, table, spread);
  std::vector<Footprint> placed;                 // one per stacked body (leaners excluded)
  std::vector<int> column_of;                    // column of each entry of `placed`
  std::vector<std::size_t> column_bases;         // index into bodies of each column's bottom box
  std::vector<std::vector<std::size_t>> columns; // body indices per column, bottom first

  int remaining = n;
  while (remaining > 0) {
    const int height = std::min<int>(remaining, 1 + static_cast<int>(rng.weighted_index(params.stack_height_odds)));
    std::vector<BoxItem> members;
    for (int i = 0; i < height; ++i) members.push_back(draw_box(rng, params.catalogue));
    remaining -= height;

    if (height == 1 && !column_bases.empty() && rng.bernoulli(params.lean_rate)) {
      const std::size_t base = column_bases[static_cast<std::size_t>(
          rng.uniform_int(0, static_cast<int>(column_bases.size()) - 1))];
      Box leaner;
      if (place_leaner(rng, members[0], layout.bodies[base].box, layout.bodies, layout.region_half, leaner)) {
        layout.items.push_back(members[0]);
        layout.bodies.push_back({leaner, members[0].mass, members[0].friction});
        continue;  // leaners do not reserve a footprint: they fall onto their column
      }
    }

    // Orientation: a single box rests on any face by the catalogue odds; stacked boxes lie flat.
    std::vector<int> up(static_cast<std::size_t>(height));
    for (int i = 0; i < height; ++i) {
      const auto& m = members[static_cast<std::size_t>(i)];
      up[static_cast<std::size_t>(i)] =
          height == 1 ? static_cast<int>(rng.weighted_index(m.vertical_axis_odds)) : smallest_axis(m.size);
    }
    // Largest footprint at the bottom.
    std::vector<int> order(static_cast<std::size_t>(height));
    for (int i = 0; i < height; ++i) order[static_cast<std::size_t>(i)] = i;
    auto area = [&](int i) {
      const auto& s = members[static_cast<std::size_t>(i)].size;
      return s.prod() / s[up[static_cast<std::size_t>(i)]];
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area(a) > area(b); });

    bool placed_column = false;
    for (int attempt = 0; attempt < params.placement_tries && !placed_column; ++attempt) {
      std::vector<Box> boxes;
      std::vector<Footprint> prints;
      const Eigen::Vector2d centre(rng.uniform(-layout.region_half.x(), layout.region_half.x()),
                                   rng.uniform(-layout.region_half.y(), layout.region_half.y()));
      double yaw = rng.uniform(0.0, kPi);
      double z = 0.002;
      bool ok = true;
      for (int k = 0; k < height && ok; ++k) {
        const int idx = order[static_cast<std::size_t>(k)];
        Box b;
        b.size = members[static_cast<std::size_t>(idx)].size;
        Eigen::Vector2d c = centre;
        if (k > 0) {
          const Footprint& below = prints.back();
          yaw = rng.bernoulli(0.5) ? below.yaw + rng.uniform_int(0, 3) * kPi / 2 + rng.uniform(-0.07, 0.07)
                                   : rng.uniform(0.0, kPi);
          const Eigen::Vector2d off(rng.uniform(-0.3, 0.3) * below.half.x(), rng.uniform(-0.3, 0.3) * below.half.y());
          c = below.centre + Eigen::Rotation2Dd(below.yaw) * off;
        }
        b.pose.q = resting_orientation(rng, up[static_cast<std::size_t>(idx)], yaw);
        b.pose.t = Eigen::Vector3d(c.x(), c.y(), 0.0);
        set_bottom(b, z);
        z = highest_z(b) + kDropGap;
        const Footprint f = footprint(b);
        ok = inside_region(f, layout.region_half, table) && !overlaps_any(f, placed, params.clearance);
        boxes.push_back(b);
        prints.push_back(f);
      }
      if (!ok) continue;
      // Leaners already dropped must not clash with the new column either.
      for (const Box& b : boxes) {
        for (const SimBody& o : layout.bodies) {
          if (sat_overlap(b, o.box) > -0.003) ok = false;
        }
      }
      if (!ok) continue;
      column_bases.push_back(layout.bodies.size());
      columns.emplace_back();
      for (int k = 0; k < height; ++k) {
        const auto& m = members[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])];
        columns.back().push_back(layout.bodies.size());
        layout.items.push_back(m);
        layout.bodies.push_back({boxes[static_cast<std::size_t>(k)], m.mass, m.friction});
        placed.push_back(prints[static_cast<std::size_t>(k)]);
        column_of.push_back(static_cast<int>(columns.size()) - 1);
      }
      placed_column = true;
      if (params.side_by_side_rate > 0.0 && height >= 2 && remaining > 0 && rng.bernoulli(params.side_by_side_rate)) {
        const BoxItem extra = draw_box(rng, params.catalogue);
        Box beside;
        const auto& col = columns.back();
        if (place_beside(rng, extra, layout.bodies[col[0]].box, layout.bodies[col[1]].box, layout.bodies, beside)) {
          columns.back().insert(columns.back().begin() + 1, layout.bodies.size());
          layout.items.push_back(extra);
          layout.bodies.push_back({beside, extra.mass, extra.friction});
          placed.push_back(footprint(beside));
          column_of.push_back(static_cast<int>(columns.size()) - 1);
          --remaining;
        }
      }
    }
    if (placed_column) continue;
    // No free spot on the table: put the boxes on top of existing columns (at most 3 high).
    for (const auto& m : members) {
      bool stacked = false;
      for (int attempt = 0; attempt < 4 * static_cast<int>(columns.size()) + 8 && !stacked; ++attempt) {
        if (columns.empty()) break;
        const auto c = static_cast<std::size_t>(rng.uniform_int(0, static_cast<int>(columns.size()) - 1));
        if (columns[c].size() >= 3) continue;
        const Box& top = layout.bodies[columns[c].back()].box;
        const Footprint below = footprint(top);
        Box b;
        b.size = m.size;
        const double yaw = rng.bernoulli(0.5) ? below.yaw + rng.uniform(-0.07, 0.07) : rng.uniform(0.0, kPi);
        const Eigen::Vector2d off(rng.uniform(-0.3, 0.3) * below.half.x(), rng.uniform(-0.3, 0.3) * below.half.y());
        const Eigen::Vector2d centre = below.centre + Eigen::Rotation2Dd(below.yaw) * off;
        b.pose.q = resting_orientation(rng, smallest_axis(m.size), yaw);
        b.pose.t = Eigen::Vector3d(centre.x(), centre.y(), 0.0);
        set_bottom(b, highest_z(top) + kDropGap);
        const Footprint f = footprint(b);
        if (!inside_region(f, layout.region_half, table)) continue;
        bool clash = false;
        for (std::size_t p = 0; p < placed.size() && !clash; ++p) {
          clash = column_of[p] != static_cast<int>(c) &&
                  footprints_overlap(f.centre, f.half, f.yaw, placed[p].centre, placed[p].half, placed[p].yaw,
                                     params.clearance);
        }
        for (const SimBody& o : layout.bodies) clash = clash || sat_overlap(b, o.box) > -0.002;
        if (clash) continue;
        columns[c].push_back(layout.bodies.size());
        layout.items.push_back(m);
        layout.bodies.push_back({b, m.mass, m.friction});
        placed.push_back(f);
        column_of.push_back(static_cast<int>(c));
        stacked = true;
      }
      if (!stacked) return std::nullopt;
    }
  }
  return layout;
}

}  // namespace ksmc::tools::tabletop_sim
