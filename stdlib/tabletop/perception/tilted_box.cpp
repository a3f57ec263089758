#include "stdlib/tabletop/perception/tilted_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "stdlib/tabletop/perception/footprint.h"
#include "stdlib/tabletop/perception/point_grid.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

bool is_tilted(const Eigen::Vector3d& n, double min_tilt) {
  const double up = std::abs(n.z());
  return up < std::cos(min_tilt) && up > std::sin(min_tilt);
}

// The minimal rectangle of a face's points in its own plane (u, v: in-plane axes).
struct PlaneRect {
  Eigen::Vector3d u, v;
  Eigen::Vector2d half;
};
PlaneRect face_rect(const Points& points, const Face& f) {
  const Eigen::Vector3d n = f.normal;
  const Eigen::Vector3d a = n.unitOrthogonal(), b = n.cross(a);
  std::vector<Eigen::Vector2d> flat;
  flat.reserve(f.points.size());
  for (int i : f.points) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - f.centroid;
    flat.emplace_back(d.dot(a), d.dot(b));
  }
  const Rect2 r = min_area_rect(flat, 0.01);
  const Eigen::Vector3d u = (r.u.x() * a + r.u.y() * b).normalized();
  return {u, n.cross(u), r.half};
}

// Whether face `f` could meet face `plane` at an edge of one box, from f's distances to
// plane's plane (1 % quantiles): its points lie on one side of it within `tolerance` (a
// neighbour's face crosses the plane), and they reach it within `gap` (a neighbour's face
// that merely comes near, a box leaning on the end of another, stops short of it).
bool meets_plane(const Points& points, const Face& f, const Face& plane, double tolerance, double gap) {
  std::vector<double> d, far;
  d.reserve(f.points.size());
  far.reserve(f.points.size());
  for (int i : f.points) {
    d.push_back((points[static_cast<std::size_t>(i)] - plane.centroid).dot(plane.normal));
    far.push_back(std::abs(d.back()));
  }
  const bool one_sided = quantile(d, 0.01) >= -tolerance || quantile(d, 0.99) <= tolerance;
  return one_sided && quantile(far, 0.01) <= gap;
}

// Whether face `f` can start a tilted box: it is tilted, has `min_points` and is no narrower
// than min_face_side in its own plane (a box face, not a bevel or a label).
bool tilted_seed(const Points& points, const Face& f, const TiltOptions& o, std::size_t min_points) {
  return f.points.size() >= min_points && is_tilted(f.normal, o.min_tilt_deg * kDeg) &&
         2.0 * face_rect(points, f).half.minCoeff() >= o.min_face_side;
}

// Whether vertical face `f` (`rect`: its outline) is the face of a box leaning about the
// face's normal: that face stays vertical, but its outline turns with the lean. Its sides are
// then at least min_tilt_deg off both vertical and horizontal, and the turned rectangle covers
// at most outline_ratio of the area of the rectangle that stands upright around the same
// points (a face cut by an occluder's diagonal edge is no rectangle at all: both cover it alike).
bool leaning_outline(const Points& points, const Face& f, const PlaneRect& rect, const TiltOptions& o) {
  if (std::abs(f.normal.z()) > std::sin(o.min_tilt_deg * kDeg)) return false;
  const double side = std::asin(std::min(1.0, std::abs(rect.u.z())));
  if (side < o.min_tilt_deg * kDeg || side > (90.0 - o.min_tilt_deg) * kDeg) return false;
  const Eigen::Vector3d across = f.normal.cross(Eigen::Vector3d::UnitZ()).normalized();
  std::vector<double> h, z;
  for (int i : f.points) {
    const Eigen::Vector3d d = points[static_cast<std::size_t>(i)] - f.centroid;
    h.push_back(d.dot(across));
    z.push_back(d.z());
  }
  const double upright = (quantile(h, 0.99) - quantile(h, 0.01)) * (quantile(z, 0.99) - quantile(z, 0.01));
  return 4.0 * rect.half.x() * rect.half.y() <= o.outline_ratio * upright;
}

// Whether vertical face `f` with `min_points` can start a tilted box by its outline.
bool outline_seed(const Points& points, const Face& f, const TiltOptions& o, std::size_t min_points) {
  return f.points.size() >= min_points && leaning_outline(points, f, face_rect(points, f), o);
}

// A leaning box rests on the table: when its lowest corner is above it, the thinnest
// extent (the one the sensor saw least of: a single face gives no thickness) is grown on
// its lower side until that corner reaches the table, unless the grown part would take
// in points of the cluster that are off the box (something is there).
void rest_on_table(const Points& points, const Eigen::Matrix3d& axes, Eigen::Vector3d& lo, Eigen::Vector3d& hi,
                   const TiltOptions& o) {
  double low = 0.0;
  for (int k = 0; k < 3; ++k) low += axes(2, k) >= 0 ? lo(k) * axes(2, k) : hi(k) * axes(2, k);
  if (low <= o.support_gap) return;
  int k = 0;
  for (int j = 1; j < 3; ++j)
    if (hi(j) - lo(j) < hi(k) - lo(k)) k = j;
  const double slope = std::abs(axes(2, k));
  if (slope < 0.1) return;
  const double grow = std::min(low / slope, o.max_support_growth);
  Eigen::Vector3d glo = lo, ghi = hi;
  (axes(2, k) > 0 ? glo(k) : ghi(k)) += axes(2, k) > 0 ? -grow : grow;
  std::size_t inside = 0;
  for (const auto& p : points) {
    const Eigen::Vector3d c = axes.transpose() * p;
    const bool in_grown = ((c - ghi).cwiseMax(glo - c)).maxCoeff() < -o.own_margin;
    const bool in_box = ((c - hi).cwiseMax(lo - c)).maxCoeff() <= o.own_margin;
    inside += in_grown && !in_box;
  }
  if (inside > o.max_support_points) return;
  lo = glo, hi = ghi;
}

// The points of face `f` in its filled part. A box face is a rectangle on the box's axes,
// so across each of its two in-plane axes its rows (slices of fill_cell) are about equally
// long where the sensor saw it. A neighbour's flush face joined to it at a corner or along
// a short stretch is a run of short rows: the face is kept from its longest row outwards
// while the rows are at least fill_ratio of that one, over both in-plane axes.
std::vector<int> face_core(const Points& points, const Face& f, const Eigen::Matrix3d& axes, const TiltOptions& o) {
  const Eigen::Vector3d n = axes.transpose() * f.normal;
  int normal_axis = 0;
  n.cwiseAbs().maxCoeff(&normal_axis);
  const double cell = o.fill_cell;
  std::vector<Eigen::Vector3d> c;
  c.reserve(f.points.size());
  for (int i : f.points) c.push_back(axes.transpose() * points[static_cast<std::size_t>(i)]);
  std::vector<bool> keep(c.size(), true);
  for (int k = 0; k < 3; ++k) {
    if (k == normal_axis) continue;
    const int j = 3 - k - normal_axis;
    double k0 = std::numeric_limits<double>::infinity();
    for (const auto& p : c) k0 = std::min(k0, p(k));
    const auto slice = [&](const Eigen::Vector3d& p) { return static_cast<std::size_t>((p(k) - k0) / cell); };
    std::vector<std::vector<long>> rows;
    for (const auto& p : c) {
      const std::size_t r = slice(p);
      if (r >= rows.size()) rows.resize(r + 1);
      rows[r].push_back(std::lround(std::floor(p(j) / cell)));
    }
    std::vector<std::size_t> length(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
      std::sort(rows[r].begin(), rows[r].end());
      length[r] = static_cast<std::size_t>(std::unique(rows[r].begin(), rows[r].end()) - rows[r].begin());
    }
    const auto longest = static_cast<std::size_t>(std::max_element(length.begin(), length.end()) - length.begin());
    const auto enough = [&](std::size_t r) {
      return static_cast<double>(length[r]) >= o.fill_ratio * static_cast<double>(length[longest]);
    };
    std::size_t first = longest, last = longest;
    while (first > 0 && enough(first - 1)) --first;
    while (last + 1 < rows.size() && enough(last + 1)) ++last;
    for (std::size_t q = 0; q < c.size(); ++q) keep[q] = keep[q] && slice(c[q]) >= first && slice(c[q]) <= last;
  }
  std::vector<int> out;
  for (std::size_t q = 0; q < c.size(); ++q)
    if (keep[q]) out.push_back(f.points[q]);
  return out;
}

// The tilted box started by face `seed` (a tilted face, or by_outline: a vertical face whose
// outline leans), or nothing when it has no box or its own points lie inside it rather than
// on its faces.
std::optional<TiltedFit> box_of_seed(const Points& points, const std::vector<Face>& faces, const Face& seed_face,
                                     bool by_outline, const TiltOptions& o) {
  const Face* const seed = &seed_face;
  const PlaneRect seed_rect = face_rect(points, *seed);
  // Faces of the same box: perpendicular to the seed and touching it. The faces of one box are
  // perpendicular to each other or lie on one plane: of two faces that are neither (a
  // neighbour's face near the seed's edge), the one with more points next to the seed is kept
  // (the box's own face runs along the edge).
  Points seed_points;
  for (int i : seed->points) seed_points.push_back(points[static_cast<std::size_t>(i)]);
  const PointGrid near_seed(seed_points, o.adjacent);
  std::vector<int> nb;
  std::vector<const Face*> box_faces{seed};
  std::vector<std::size_t> touching{seed->points.size()};
  for (const Face& f : faces) {
    if (&f == seed || std::abs(f.normal.dot(seed->normal)) > std::sin(o.perpendicular_deg * kDeg)) continue;
    if (!meets_plane(points, f, *seed, o.side_tolerance, o.edge_gap) ||
        !meets_plane(points, *seed, f, o.side_tolerance, o.edge_gap))
      continue;
    const auto near = static_cast<std::size_t>(std::count_if(f.points.begin(), f.points.end(), [&](int i) {
      near_seed.neighbours(points[static_cast<std::size_t>(i)], nb);
      return !nb.empty();
    }));
    if (near == 0) continue;
    // Faces f cannot share a box with: those neither perpendicular to it nor on its plane.
    std::vector<std::size_t> clash;
    for (std::size_t k = 1; k < box_faces.size(); ++k) {
      const Face& g = *box_faces[k];
      const double c = std::abs(f.normal.dot(g.normal));
      const bool same_plane = c > std::cos(o.perpendicular_deg * kDeg) &&
                              std::abs((f.centroid - g.centroid).dot(g.normal)) <= o.side_tolerance;
      if (c > std::sin(o.perpendicular_deg * kDeg) && !same_plane) clash.push_back(k);
    }
    if (!clash.empty()) {
      const bool more = std::all_of(clash.begin(), clash.end(), [&](std::size_t k) { return near > touching[k]; });
      if (!more) continue;
      for (auto k = clash.rbegin(); k != clash.rend(); ++k) {
        box_faces.erase(box_faces.begin() + static_cast<std::ptrdiff_t>(*k));
        touching.erase(touching.begin() + static_cast<std::ptrdiff_t>(*k));
      }
    }
    box_faces.push_back(&f);
    touching.push_back(near);
  }
  // Two faces of one box meet along an edge and span it alike: a face that runs past the seed
  // along their common edge by more than max_overreach at the upper end is a taller neighbour's
  // face flush with the box's (an upright carton's front in the plane of the side of a box
  // leaning on it). Past the lower end it may be the wall under a sloping top (a carton's gable
  // roof): kept, and the box then holds that wall inside it (max_interior). Along a level edge
  // both ends count.
  if (o.max_overreach > 0.0) {
    const auto span = [&](const Face& f, const Eigen::Vector3d& e) {
      std::vector<double> t;
      t.reserve(f.points.size());
      for (int i : f.points) t.push_back(points[static_cast<std::size_t>(i)].dot(e));
      return std::pair{quantile(t, 0.01), quantile(t, 0.99)};
    };
    std::vector<const Face*> kept{seed};
    for (std::size_t k = 1; k < box_faces.size(); ++k) {
      Eigen::Vector3d e = seed->normal.cross(box_faces[k]->normal).normalized();
      if (e.z() < 0.0) e = -e;  // rising along e
      const auto [s0, s1] = span(*seed, e);
      const auto [f0, f1] = span(*box_faces[k], e);
      const bool level = e.z() < std::sin(o.min_tilt_deg * kDeg);
      if ((!level || f0 >= s0 - o.max_overreach) && f1 <= s1 + o.max_overreach) kept.push_back(box_faces[k]);
    }
    box_faces = std::move(kept);
  }
  // A vertical seed gives the box's tilt by its outline, and no thickness: another face must.
  if (by_outline && box_faces.size() < 2) return std::nullopt;
  Eigen::Matrix3d axes;
  axes.col(0) = seed->normal;
  const Eigen::Vector3d second = box_faces.size() > 1 && !by_outline ? box_faces[1]->normal : seed_rect.u;
  axes.col(1) = (second - second.dot(axes.col(0)) * axes.col(0)).normalized();
  axes.col(2) = axes.col(0).cross(axes.col(1));

  std::vector<std::vector<int>> cores;
  for (const Face* f : box_faces) cores.push_back(face_core(points, *f, axes, o));
  Eigen::Vector3d lo, hi;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> s;
    for (const auto& core : cores)
      for (int i : core) s.push_back(points[static_cast<std::size_t>(i)].dot(axes.col(k)));
    lo(k) = quantile(s, o.trim);
    hi(k) = quantile(s, 1.0 - o.trim);
  }
  rest_on_table(points, axes, lo, hi, o);
  Eigen::Vector3d size = (hi - lo).cwiseMax(o.min_size);
  const Eigen::Vector3d centre = axes * (0.5 * (lo + hi));
  canonical_axes(axes, size);

  TiltedFit out;
  out.box.size = size;
  out.box.pose.t = centre;
  out.box.pose.q = Eigen::Quaterniond(axes).normalized();
  std::size_t own = 0, interior = 0;
  for (const auto& p : points) {
    const Eigen::Vector3d d = (axes.transpose() * (p - centre)).cwiseAbs() - 0.5 * size;
    if (d.maxCoeff() > o.own_margin) {
      out.rest.push_back(p);
    } else {
      ++own;
      interior += d.maxCoeff() < -o.interior_depth;
    }
  }
  if (static_cast<double>(interior) > o.max_interior * static_cast<double>(own)) return std::nullopt;
  return out;
}

}  // namespace

void canonical_axes(Eigen::Matrix3d& axes, Eigen::Vector3d& size) {
  int up = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(axes(2, k)) > std::abs(axes(2, up))) up = k;
  const int a = (up + 1) % 3, b = (up + 2) % 3;
  const int first = std::abs(axes(0, a)) >= std::abs(axes(0, b)) ? a : b;
  const int second = first == a ? b : a;
  Eigen::Matrix3d r;
  r.col(2) = (axes(2, up) < 0 ? -1.0 : 1.0) * axes.col(up);
  r.col(0) = (axes(0, first) < 0 ? -1.0 : 1.0) * axes.col(first);
  r.col(1) = r.col(2).cross(r.col(0));
  size = Eigen::Vector3d(size(first), size(second), size(up));
  axes = r;
}

std::optional<TiltedFit> fit_tilted_box(const Points& points, const TiltOptions& o) {
  // A quick look on a sparse copy first: most clusters are upright boxes.
  const Points sparse = voxel_subsample(points, o.probe_voxel);
  FaceOptions probe = o.faces;
  probe.normal_radius = std::max(probe.normal_radius, 2.0 * o.probe_voxel);
  probe.grow_radius = std::max(probe.grow_radius, 2.0 * o.probe_voxel);
  probe.min_points = 10;
  probe.row_factor = 0.0;  // the sparse copy's radii already span the rows
  const auto probe_points = static_cast<std::size_t>(
      static_cast<double>(o.min_face_points) * static_cast<double>(sparse.size()) / static_cast<double>(points.size()));
  const std::vector<Face> sparse_faces = planar_faces(sparse, probe);
  const bool any_tilted = std::any_of(sparse_faces.begin(), sparse_faces.end(),
                                      [&](const Face& f) { return tilted_seed(sparse, f, o, probe_points); });
  if (!any_tilted && (!o.leaning_outlines || std::none_of(sparse_faces.begin(), sparse_faces.end(), [&](const Face& f) {
        return outline_seed(sparse, f, o, probe_points);
      })))
    return std::nullopt;

  // The tilted faces from the largest, then (with none that gives a box) the vertical faces
  // whose outline leans: the first whose box has its points on its faces.
  std::vector<Face> faces = planar_faces(points, o.faces);
  if (o.join_split)
    join_coplanar_faces(points, faces, o.faces, [&](const Face& f) { return is_tilted(f.normal, o.min_tilt_deg * kDeg); });
  bool tilted_face = false;
  for (const Face& f : faces) {
    if (!tilted_seed(points, f, o, o.min_face_points)) continue;
    tilted_face = true;
    if (std::optional<TiltedFit> fit = box_of_seed(points, faces, f, false, o)) return fit;
  }
  if (tilted_face || !o.leaning_outlines) return std::nullopt;
  for (const Face& f : faces)
    if (outline_seed(points, f, o, o.min_face_points))
      if (std::optional<TiltedFit> fit = box_of_seed(points, faces, f, true, o)) return fit;
  return std::nullopt;
}

}  // namespace ksmc::stdlib::tabletop::perception
