// The table-top kit's blocks as generated code calls them (docs/binding.md §3, §4): one
// C++ function or factory per `extern` of stdlib/tabletop.ksm, parameters in signature order,
// numbers in base units (m, rad, px). Per-binding blocks (extractors) take the Scene first;
// factories (prior, likelihood, proposal, output) return the kit's block values.
//
//   extract stable(o) = obb.stable(pose[o], size[o], tol = 10 deg);
//     -> blk::obb::stable(s, s.se3(c[0]), s.vec3(c[0]), 0.17453292519943295)
//   output scene.decisions(false_est = falseEst, hidden = hidden);
//     -> blk::scene::decisions(kPred_falseEst, kPred_hidden)
//
// The extractors compute the relations of stdlib/tabletop/extract_*.h from the Scene's cached
// geometry. Tolerances the .ksm signatures do not expose are the stdlib defaults of
// EvidenceParams: the near-vertical tolerances (raised to the block's eps when larger), the
// vertical cone, higher's 15 mm, and the intersect depth below which a contact is a touch.
#pragma once

#include <cstdint>
#include <optional>
#include <variant>

#include "runtime/domain/binding.h"
#include "stdlib/tabletop/block_scene.h"

namespace ksmc::stdlib::tabletop::blocks {

// Moves the proposal sources make (`makes perturb`, `makes fit`): each is its own reverse.
enum class Move { perturb, fit };

// Global prior `mln`: the Markov logic score of the state (kit: PriorQuantity).
struct MlnPrior {};
using Prior = std::variant<MlnPrior>;

// Likelihood `keypoints.gaussian` (eq. 4.4; kit_likelihood.h).
struct KeypointGaussian {
  double sigma_px = 1.0;
  bool robust = false;
  double outlier_px = 20.0;
  double estimate_sigma_t = 0.0;  // [m] the input pose estimate as a measurement; 0: off
  double estimate_sigma_r = 0.0;  // [rad]
  // σ (and outlier_px with it) raised to the scene's own pixel noise when that is larger
  // (pixel_noise.h; kit::scene_likelihood).
  bool sigma_from_scene = false;
};
// Likelihood `cloud.surface` (cloud_likelihood.h): a depth cloud's points on their boxes'
// surfaces, and, with free_space_cost > 0, the rays a box blocks.
struct CloudSurface {
  double sigma = 0.004;           // [m]
  bool robust = true;
  double outlier = 0.02;          // [m] cap of a point's distance in the robust variant
  double free_space_cost = 0.0;   // log-likelihood per blocked ray; 0: off
  double inside_sigma = 0.02;     // [m] scale of the distance of points inside the box
  double voxel = 0.005;           // [m] the points are thinned to one per cube this wide; 0: all
};
// A domain's likelihood: the product of its likelihood items (the generated binding writes
// `b.likelihood = first; b.likelihood *= next; ...`), each block at most once (ksmc check).
// The keypoint fields are those of `keypoints.gaussian` when it is one of them.
struct Likelihood : KeypointGaussian {
  bool keypoint_term = false;          // keypoints.gaussian is a factor
  std::optional<CloudSurface> cloud;   // cloud.surface is a factor
  Likelihood& operator*=(const Likelihood& other);
};

// Proposal source `pose.perturb` (the DDMCMC refine move, refine_kernel.h).
struct PosePerturb {
  double sigma_t = 0.003;  // [m]
  double sigma_r = 0.0;    // [rad]
  int candidates = 20;
};
// Proposal source `pose.fit` (the keypoint-fit move, fit_kernel.h): an independence proposal
// from the Laplace approximation of the object's keypoint likelihood (keypoint_fit.h), its
// covariance scaled by scale². With estimate_scale > 0 it is the equal mixture of that and of
// N(input estimate, estimate_scale² · diag(σ_t², σ_r²)), σ the likelihood's estimate_sigma_*.
struct PoseFit {
  double scale = 0.5;
  double estimate_scale = 0.0;  // 0: the keypoint fit alone
};
using Source = std::variant<PosePerturb, PoseFit>;

// Output `scene.decisions`: the query predicates reported per object as false_prob /
// hidden_prob with their 0.4 / 0.6 decisions (program predicate ids).
struct Decisions {
  std::int32_t false_est = -1;
  std::int32_t hidden = -1;
};
using Output = Decisions;

namespace obb {
// The box's up axis within `tol` [rad] of the table normal (extract_stable.h).
bool stable(const Scene& s, Se3 pose, Vec3 size, double tol);
// The box's up axis more than k standard deviations of the scene's resting-tilt noise
// (Scene::tilt_sigma, tilt_noise.h) and more than min_angle [rad] from the table normal: it
// does not rest on a level face. Never holds in a scene with fewer than 3 objects resting on a face.
bool tilted(const Scene& s, Se3 pose, Vec3 size, double k, double min_angle);
// The box's lowest point lies below the table top by more than k standard deviations of the
// scene's resting-gap noise (Scene::gap_sigma) and more than min_depth [m]: it cuts into the
// table. Never holds for the table itself.
bool sunk(const Scene& s, Se3 pose, Vec3 size, double k, double min_depth);
// Touching without intersecting: gap at most eps [m] (extract_contact.h).
bool contact(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double eps);
// Penetration deeper than eps [m], or containment (extract_intersect.h).
bool intersect(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double eps);
// a's lowest face at or above b's highest face (extract_higher.h).
bool higher(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b);
// Constant o touches no other body, the table included (gap above eps [m] from every body).
// The table itself never hovers.
bool hover(const Scene& s, std::int32_t o, double eps);
// The boxes share at least `min_fraction` of the smaller one's volume, both shrunk by the
// scene's gap-noise standard deviation on every side (extract_overlap.h).
bool overlap(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double min_fraction);
// a's tilt is smaller than b's by more than margin [rad] (extract_overlap.h).
bool flatter(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double margin);
// Constant o rests on other boxes and not on the table (its supporters: the bodies it touches
// in the sense of hover with tolerance eps and is `higher` than), and its centre lies beyond
// their upward faces by more than margin [m] (extract_overhang.h). It reads the bodies o
// touches, like hover: a move changes it only for bodies touching the moved one.
bool overhang(const Scene& s, std::int32_t o, double eps, double margin);
// Constant o is tilted more than `tol` [rad] from resting on a face, and is held as a leaning
// or propped box is: it touches, within eps [m] and without intersecting, a surface under it
// (the table, or a box resting on a face that o is `higher` than), and it touches a different
// body on the side it would fall to (the side of its centre from its lowest vertex), cutting
// into it at most sqrt(2) times as deep as the scene's vertical tolerance
// (Scene::vertical_tolerance: the pose noise of one estimate; the cut is the difference of two):
// a wall it leans on, or a lower box its raised end rests on. It reads the bodies o touches,
// like overhang.
bool leaning(const Scene& s, std::int32_t o, double tol, double eps);
// Constant a sits on what it rests on more snugly than b does: the gap between a's lowest
// point and the top of the nearest body it rests on (the bodies it touches within eps [m]
// and is `higher` than, the table included) is smaller than b's by more than margin times
// the scene's gap noise (Scene::gap_sigma). False when either rests on no visible body (it
// may rest on a hidden one). It reads the bodies a and b touch, like overhang.
bool snugger(const Scene& s, std::int32_t a, std::int32_t b, double eps, double margin);
// Box a stands between the camera and at least min_keypoints (and min_fraction) of object
// b's keypoints, by its core shrunk by margin [m] and up to margin before each keypoint
// (extract_blocks.h). False for the table and for one body.
bool blocks(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double margin, int min_keypoints,
            double min_fraction);
// Box a stands in front of the part of object b's camera-facing surface where b, at the
// density of its keypoints, would show at least min_expected keypoints; a counts by its core
// shrunk by margin [m] (extract_hides.h). False for the table, for one body and for an object
// without keypoints.
bool hides(const Scene& s, Se3 pose_a, Vec3 size_a, Se3 pose_b, Vec3 size_b, double margin, double min_expected);
}  // namespace obb

namespace scene {
bool is_table(const Scene& s, std::int32_t o);
Output decisions(std::int32_t false_est, std::int32_t hidden);
}  // namespace scene

Prior mln();

namespace keypoints {
Likelihood gaussian(double sigma, bool robust, double outlier_px, double estimate_sigma_t, double estimate_sigma_r,
                    bool sigma_from_scene);
}  // namespace keypoints

namespace cloud {
Likelihood surface(double sigma, bool robust, double outlier, double free_space_cost, double inside_sigma,
                   double voxel);
}  // namespace cloud

namespace pose {
Source perturb(double sigma_t, double sigma_r, int candidates);
Source fit(double scale, double estimate_scale);
}  // namespace pose

// Whether bodies a and b touch in the sense of obb::hover with tolerance eps.
bool touching(const Scene& s, std::int32_t a, std::int32_t b, double eps);
// For every body j: a bit per tolerance hover was evaluated with (Scene::hover_tolerances),
// set when j touches body c. A move of c can change hover(j) only where this changes.
std::vector<std::uint32_t> touching_row(const Scene& s, std::int32_t c);

using Binding = runtime::domain::Binding<Scene, Prior, Likelihood, Move, Source, Output>;

}  // namespace ksmc::stdlib::tabletop::blocks
