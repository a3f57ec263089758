// Proposal densities of the segment kernel pairs, as pure functions of the current scene
// (so a kernel's reverse density is computed with the reverse kernel's own weighting on
// the proposed state). See docs/segments.md for the moves.
//
//  BIRTH  choose candidate c with weight (1 + unexplained inliers of c)^power, draw both
//         endpoints around c's with an isotropic Gaussian of `jitter`, canonicalise:
//           q(s) = sum_c w_c [N(s.a; c.a) N(s.b; c.b) + N(s.a; c.b) N(s.b; c.a)]
//  DEATH  choose line k with weight 1 / (1 + points it explains within `explain`).
//  SPLIT  choose a line uniformly; choose a split option of its support histogram; draw the
//         new inner endpoints p1, p2 around the option's gap ends; the pieces are
//         canonical(a, p1) and canonical(p2, b).
//  MERGE  choose a line uniformly and a partner with weight exp(-angle/angle_scale) /
//         (eps + endpoint gap); the merged line joins the farthest pair of endpoints (one of
//         each); P({i, j}) sums both orders.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "stdlib/segments/detect.h"
#include "stdlib/segments/scene.h"

namespace ksmc::stdlib::segments {

struct BirthParams {
  double jitter = 0.02;  // metres
  double power = 2.0;
  double explained = 0.03;  // a point within this distance of a line is explained
};
struct DeathParams {
  double explain = 0.05;
};
struct SplitParams {
  double bin = 0.10;
  double gap_weight = 20.0;
  double jitter = 0.02;
  double near = 0.05;  // points within this distance of the line make its histogram
};
// JITTER (its own reverse): with probability shift_prob the whole segment moves, with
// slide_prob one endpoint slides along the segment's line, otherwise one endpoint moves.
struct JitterParams {
  double sigma = 0.02;
  double shift_prob = 0.2;
  double slide = 0.05;
  double slide_prob = 0.4;
};

struct MergeParams {
  double eps = 0.05;
  double angle_scale = 0.17453292519943295;
};

double log_normal2(Vec2 x, Vec2 mean, double sigma);  // isotropic 2D Gaussian density, log

// ---- birth / death ----
// Normalised candidate probabilities in the scene's current state (empty: no candidate).
std::vector<double> birth_probabilities(const Scene& scene, const std::vector<Candidate>& cands,
                                        const BirthParams& p);
double birth_log_density(const Segment& s, const std::vector<double>& probs, const std::vector<Candidate>& cands,
                         const BirthParams& p);
// Normalised line probabilities (empty when there is no line).
std::vector<double> death_probabilities(const Scene& scene, const DeathParams& p);

// ---- split / merge ----
struct SplitOption {
  double t_lo = 0.0, t_hi = 0.0;  // gap ends along a -> b, in [0, 1]
  double prob = 0.0;              // normalised
};
std::vector<SplitOption> split_options(const std::vector<Vec2>& points, const Segment& s, const SplitParams& p);
// log density of the inner endpoints (p1 next to s.a, p2 next to s.b).
double split_log_density(const Segment& s, Vec2 p1, Vec2 p2, const std::vector<SplitOption>& options,
                         const SplitParams& p);
// The pieces of a split.
std::pair<Segment, Segment> split_pieces(const Segment& s, Vec2 p1, Vec2 p2);

struct Merged {
  Segment seg;     // canonical
  Vec2 p1, p2;     // the dropped endpoints: p1 on the piece holding seg.a, p2 on the other
};
Merged merge_of(const Segment& s, const Segment& t);

double partner_weight(const Segment& s, const Segment& t, const MergeParams& p);
// log P(the unordered pair {i, j} is chosen) among `lines` (needs at least 2 lines).
double merge_pair_log_prob(const std::vector<Line>& lines, std::size_t i, std::size_t j, const MergeParams& p);

}  // namespace ksmc::stdlib::segments
