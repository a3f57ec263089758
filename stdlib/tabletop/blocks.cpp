#include "stdlib/tabletop/blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "stdlib/tabletop/extract_blocks.h"
#include "stdlib/tabletop/extract_contact.h"
#include "stdlib/tabletop/extract_hides.h"
#include "stdlib/tabletop/extract_higher.h"
#include "stdlib/tabletop/extract_intersect.h"
#include "stdlib/tabletop/extract_overhang.h"
#include "stdlib/tabletop/extract_overlap.h"
#include "stdlib/tabletop/extract_stable.h"

namespace ksmc::stdlib::tabletop::blocks {

namespace {

const EvidenceParams kDefaults{};

bool one_body(Se3 pose, Vec3 size) { return pose.body >= 0 && pose.body == size.body; }

Obb box_of(const Scene& s, Se3 pose, Vec3 size) {
  return one_body(pose, size) ? s.box(pose.body) : Obb::from_pose(*pose.pose, *size.size);
}

// Pair geometry with the exact distance wherever it is at most `cutoff` (never below the
// stdlib's largest contact tolerance, so one computation serves every block of the pair).
PairGeometry geometry(const Scene& s, Se3 pa, Vec3 sa, Se3 pb, Vec3 sb, double cutoff) {
  cutoff = std::max(cutoff, kDefaults.max_contact_eps());
  if (one_body(pa, sa) && one_body(pb, sb) && pa.body != pb.body) return s.pair(pa.body, pb.body, cutoff);
  return pair_geometry(box_of(s, pa, sa), box_of(s, pb, sb), cutoff);
}

// The near-vertical tolerances are the scene's, derived from its gap noise (gap_noise.h).
// The near-vertical contact tolerance is the scene's, derived from its gap noise
// (gap_noise.h): a gap beyond 3 sigma is not a touch. Penetration keeps the stdlib's 15 mm
// (a measured choice: deriving it too made more real pairs intersect, docs/tabletop_kit.md).
EvidenceParams contact_params(const Scene& s, double eps) {
  EvidenceParams p;
  p.contact_eps = eps;
  p.vertical_contact_eps = std::max(s.vertical_tolerance(), eps);
  return p;
}

EvidenceParams intersect_params(double eps) {
  EvidenceParams p;
  p.intersect_eps = eps;
  p.vertical_intersect_eps = std::max(kDefaults.vertical_intersect_eps, eps);
  return p;
}

// Body o rests on body b: it touches b within eps (blocks.h: touching) and lies `higher`
// than b. The supporters overhang and snugger read.
bool rests_on(const Scene& s, std::int32_t o, std::int32_t b, double eps) {
  return b != o && touching(s, o, b, eps) && extract_higher(s.box(o), s.box(b), kDefaults);
}

// How far body o's lowest point lies from the top of the nearest body it rests on
// (rests_on, the table included), but not one it cuts into from the side. Infinity when it
// rests on none.
double seat_gap(const Scene& s, std::int32_t o, double eps) {
  if (const std::optional<double> known = s.memo(o, eps)) return *known;
  double best = std::numeric_limits<double>::infinity();
  const Obb& box = s.box(o);
  const EvidenceParams p = contact_params(s, eps);
  for (std::size_t j = 0; j < s.bodies(); ++j) {
    const auto b = static_cast<std::int32_t>(j);
    if (!rests_on(s, o, b, eps)) continue;
    const PairGeometry& g = s.pair(o, b, std::max(p.max_contact_eps(), kDefaults.max_contact_eps()));
    if (g.overlapping && !(g.stacked && is_near_vertical(g.direction, p))) continue;  // a side cut
    best = std::min(best, std::abs(box.min_z() - s.box(b).max_z()));
  }
  s.set_memo(o, eps, best);
  return best;
}

}  // namespace

namespace obb {

bool stable(const Scene& s, Se3 pose, Vec3 size, double tol) {
  s.relation_params_mut().stable_tol_rad = tol;
  return tilt_angle(box_of(s, pose, size)) <= tol;
}

bool tilted(const Scene& s, Se3 pose, Vec3 size, double k, double min_angle) {
  return tilt_angle(box_of(s, pose, size)) > std::max(k * s.tilt_sigma(), min_angle);
}

bool sunk(const Scene& s, Se3 pose, Vec3 size, double k, double min_depth) {
  constexpr std::int32_t kTable = 0;  // Scene::is_table
  if (one_body(pose, size) && s.is_table(pose.body)) return false;
  return s.box(kTable).max_z() - box_of(s, pose, size).min_z() > std::max(k * s.gap_sigma(), min_depth);
}

bool contact(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double eps) {
  const EvidenceParams p = contact_params(s, eps);
  EvidenceParams& rec = s.relation_params_mut();
  rec.contact_eps = p.contact_eps;
  rec.vertical_contact_eps = p.vertical_contact_eps;
  return contact_from_geometry(geometry(s, pose_a, size_a, pose_b, size_b, p.max_contact_eps()), p);
}

bool intersect(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double eps) {
  const EvidenceParams p = intersect_params(eps);
  EvidenceParams& rec = s.relation_params_mut();
  rec.intersect_eps = p.intersect_eps;
  rec.vertical_intersect_eps = p.vertical_intersect_eps;
  return intersect_from_geometry(geometry(s, pose_a, size_a, pose_b, size_b, 0.0), p);
}

bool higher(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b) {
  return extract_higher(box_of(s, pose_a, size_a), box_of(s, pose_b, size_b), kDefaults);
}

bool hover(const Scene& s, std::int32_t o, double eps) {
  if (s.is_table(o)) return false;  // the table rests on the ground
  s.note_hover_tolerance(eps);
  for (std::size_t j = 0; j < s.bodies(); ++j)
    if (static_cast<std::int32_t>(j) != o && touching(s, o, static_cast<std::int32_t>(j), eps)) return false;
  return true;
}

bool overlap(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double min_fraction) {
  if (one_body(pose_a, size_a) && one_body(pose_b, size_b) && pose_a.body == pose_b.body) return false;
  // Only a pair whose solids overlap can share volume (the cached SAT test decides cheaply).
  if (!geometry(s, pose_a, size_a, pose_b, size_b, 0.0).overlapping) return false;
  return extract_overlap(box_of(s, pose_a, size_a), box_of(s, pose_b, size_b), s.gap_sigma(), min_fraction);
}

bool flatter(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double margin) {
  return extract_flatter(box_of(s, pose_a, size_a), box_of(s, pose_b, size_b), margin);
}

bool overhang(const Scene& s, std::int32_t o, double eps, double margin) {
  if (s.is_table(o)) return false;
  s.note_hover_tolerance(eps);  // touching_row then tracks the bodies this atom reads
  std::vector<Obb> supporters;
  for (std::size_t j = 0; j < s.bodies(); ++j) {
    const auto b = static_cast<std::int32_t>(j);
    if (!rests_on(s, o, b, eps)) continue;
    if (s.is_table(b)) return false;  // resting on the table: nothing to overhang
    supporters.push_back(s.box(b));
  }
  return extract_overhang(s.box(o), supporters, margin);
}

bool leaning(const Scene& s, std::int32_t o, double tol, double eps) {
  const Obb& box = s.box(o);
  if (s.is_table(o) || tilt_angle(box) <= tol) return false;
  s.note_hover_tolerance(eps);  // touching_row then tracks the bodies this atom reads
  // The side the box falls to without the body it leans on: from its lowest vertex (on the
  // edge it stands on) towards its centre, in the table plane.
  const auto corners = box.vertices();
  const Eigen::Vector3d low = *std::min_element(corners.begin(), corners.end(),
                                                [](const auto& a, const auto& b) { return a.z() < b.z(); });
  const Eigen::Vector2d falls = (box.center - low).head<2>();
  const EvidenceParams cut = intersect_params(kDefaults.intersect_eps);
  // Two different bodies: one under it (the table, or a level box it is higher than) and one
  // on the side it would fall to, beside it (a wall) or under its raised end (a lower box it
  // is propped on). A single body cannot be both.
  std::int32_t base = -1, held = -1;
  int bases = 0, helds = 0;
  for (std::size_t j = 0; j < s.bodies(); ++j) {
    const auto b = static_cast<std::int32_t>(j);
    if (b == o || !touching(s, o, b, eps)) continue;
    // A surface under it is not cut into. The body it leans on may be, as deep as the pose
    // noise of two estimates reaches: pose noise puts a leaning box's estimate on either side
    // of the face it leans on, and that face's own estimate too. Each is within the scene's
    // tolerance (Scene::vertical_tolerance, 3 sigma), so their difference within sqrt(2) times
    // it (the cloud front end's well-fitted leaning boxes cut 4-8 mm into what they lean on).
    const PairGeometry& g = s.pair(o, b, kDefaults.max_contact_eps());
    const bool cut_into = intersect_from_geometry(g, cut);
    const bool within_noise = !g.contained && g.depth <= std::sqrt(2.0) * s.vertical_tolerance();
    const Obb& other = s.box(b);
    const bool under = !cut_into && (s.is_table(b) || (tilt_angle(other) <= tol && extract_higher(box, other, kDefaults)));
    const bool falling_side = (!cut_into || within_noise) && !s.is_table(b) &&
                              (other.closest_point(box.center) - box.center).head<2>().dot(falls) > 0.0;
    if (under) base = b, ++bases;
    if (falling_side) held = b, ++helds;
  }
  return bases > 0 && helds > 0 && (bases > 1 || helds > 1 || base != held);
}

bool snugger(const Scene& s, std::int32_t a, std::int32_t b, double eps, double margin) {
  if (a == b || s.is_table(a) || s.is_table(b)) return false;
  s.note_hover_tolerance(eps);  // touching_row then tracks the bodies this atom reads
  const double gap_a = seat_gap(s, a, eps), gap_b = seat_gap(s, b, eps);
  return std::isfinite(gap_b) && gap_a + margin * s.gap_sigma() < gap_b;
}

namespace {

// The object whose keypoints a line-of-sight atom reads: b's body's, at the pose b stands for;
// null when b is not one object's (the table, a mixed pose and size) or a and b are one body,
// or a is the table.
const SceneObject* keypoint_object(const Scene& s, Se3 pose_a, Se3 pose_b, Vec3 size_b) {
  if (pose_b.body < 1 || pose_b.body != size_b.body || pose_a.body == pose_b.body || s.is_table(pose_a.body)) return nullptr;
  return &s.input().objects[static_cast<std::size_t>(pose_b.body - 1)];
}

Eigen::Vector3d camera_of(const Scene& s) { return s.input().table_in_camera.inverse().t; }

}  // namespace

bool blocks(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double margin, int min_keypoints,
            double min_fraction) {
  const SceneObject* seen = keypoint_object(s, pose_a, pose_b, size_b);
  return seen != nullptr && extract_blocks(box_of(s, pose_a, size_a), *pose_b.pose, seen->keypoints_model, camera_of(s),
                                           margin, min_keypoints, min_fraction);
}

bool hides(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double margin, double min_expected) {
  const SceneObject* seen = keypoint_object(s, pose_a, pose_b, size_b);
  return seen != nullptr && extract_hides(box_of(s, pose_a, size_a), box_of(s, pose_b, size_b),
                                          static_cast<int>(seen->keypoints_model.size()), camera_of(s), margin,
                                          min_expected);
}

}  // namespace obb

bool touching(const Scene& s, std::int32_t a, std::int32_t b, double eps) {
  // contact or intersect, whatever the intersect depth: overlapping, or a gap within the
  // contact tolerance of its direction (contact_from_geometry).
  const EvidenceParams p = contact_params(s, eps);
  const PairGeometry& g = s.pair(a, b, std::max(p.max_contact_eps(), kDefaults.max_contact_eps()));
  if (g.overlapping) return true;
  const double tol = g.stacked && is_near_vertical(g.direction, p) ? p.vertical_contact_eps : p.contact_eps;
  return g.distance <= tol;
}

std::vector<std::uint32_t> touching_row(const Scene& s, std::int32_t c) {
  const auto& tols = s.hover_tolerances();
  std::vector<std::uint32_t> row(s.bodies(), 0);
  for (std::size_t j = 0; j < s.bodies(); ++j) {
    if (static_cast<std::int32_t>(j) == c) continue;
    for (std::size_t t = 0; t < tols.size() && t < 32; ++t)
      if (touching(s, c, static_cast<std::int32_t>(j), tols[t])) row[j] |= 1u << t;
  }
  return row;
}

namespace scene {

bool is_table(const Scene& s, std::int32_t o) { return s.is_table(o); }
Output decisions(std::int32_t false_est, std::int32_t hidden) { return Decisions{false_est, hidden}; }

}  // namespace scene

Prior mln() { return MlnPrior{}; }

Likelihood& Likelihood::operator*=(const Likelihood& other) {
  if (other.keypoint_term) {
    static_cast<KeypointGaussian&>(*this) = other;
    keypoint_term = true;
  }
  if (other.cloud) cloud = other.cloud;
  return *this;
}

namespace keypoints {
Likelihood gaussian(double sigma, bool robust, double outlier_px, double estimate_sigma_t, double estimate_sigma_r,
                    bool sigma_from_scene) {
  Likelihood l;
  static_cast<KeypointGaussian&>(l) = KeypointGaussian{sigma, robust, outlier_px, estimate_sigma_t, estimate_sigma_r, sigma_from_scene};
  l.keypoint_term = true;
  return l;
}
}  // namespace keypoints

namespace cloud {
Likelihood surface(double sigma, bool robust, double outlier, double free_space_cost, double inside_sigma,
                   double voxel) {
  Likelihood l;
  l.cloud = CloudSurface{sigma, robust, outlier, free_space_cost, inside_sigma, voxel};
  return l;
}
}  // namespace cloud

namespace pose {
Source perturb(double sigma_t, double sigma_r, int candidates) { return PosePerturb{sigma_t, sigma_r, candidates}; }
Source fit(double scale, double estimate_scale) { return PoseFit{scale, estimate_scale}; }
}  // namespace pose

}  // namespace ksmc::stdlib::tabletop::blocks
