// The segments kit's blocks: what generated `<domain>_model.cpp` calls for a domain file
// written against stdlib/segments.ksm (docs/binding.md §3, docs/extending.md). One C++
// declaration per `extern` signature, arguments in signature order, numbers in base units
// (metres, radians):
//   extractors, functions and term priors (`-> real`) take `const Scene&` first and are
//   called per ground atom / binding; factories (global priors, the likelihood, proposal
//   sources) return the kit's parameter values, read by stdlib/segments/kit.
// A C++ keyword gets a trailing underscore (`seg.short` -> seg::short_).
#pragma once

#include <cstdint>
#include <variant>
#include <vector>

#include "runtime/domain/binding.h"
#include "stdlib/segments/detect.h"
#include "stdlib/segments/geometry.h"
#include "stdlib/segments/proposals.h"
#include "stdlib/segments/scene.h"

namespace ksmc::stdlib::segments::blocks {

// The model state generated code reads: the model's segments in scene order; constant i of
// the domain's run-time type is segment i.
class Scene {
 public:
  explicit Scene(const segments::Scene& state) : state_(&state) {}
  const Segment& segment(std::int32_t i) const { return state_->lines()[static_cast<std::size_t>(i)].seg; }
  const std::vector<Line>& segments() const { return state_->lines(); }
  std::size_t size() const { return state_->size(); }

 private:
  const segments::Scene* state_;
};

// The moves proposal sources make (`makes birth / death`, `makes split / merge`, `makes jitter`).
enum class Move { birth, death, split, merge, jitter };

// ---- extractors ----------------------------------------------------------------------------
namespace seg {
bool touching(const Scene& s, const Segment& a, const Segment& b, double gap);
bool perpendicular(const Scene& s, const Segment& a, const Segment& b, double tol);
bool parallel(const Scene& s, const Segment& a, const Segment& b, double tol);
bool close(const Scene& s, const Segment& a, const Segment& b, double dist);
bool short_(const Scene& s, const Segment& a, double max_length);
}  // namespace seg

// ---- functions and term priors --------------------------------------------------------------
double endpoint_gap(const Scene& s, const Segment& a, const Segment& b);
double line_offset(const Scene& s, const Segment& a, const Segment& b);
double corner_angle_error(const Scene& s, const Segment& a, const Segment& b);
double parallel_angle_error(const Scene& s, const Segment& a, const Segment& b);
// Zero-mean Gaussian log density of x, without its normalising constant: -x^2 / (2 sigma^2).
// (A constant per holding binding would reward or penalise the number of bindings.)
double gaussian(const Scene& s, double x, double sigma);
double gaussian_angle(const Scene& s, double x, double sigma);

// ---- global priors ---------------------------------------------------------------------------
// `prior seg.complexity(per_segment, per_metre)`: -per_segment per segment - per_metre per metre.
struct Complexity {
  double per_segment = 6.0;
  double per_metre = 2.0;
};
// `prior mln`: log Z(evidence) - log Z(no evidence atom holds) for the current segments.
struct MlnPrior {};
using Prior = std::variant<Complexity, MlnPrior>;
Prior mln();
namespace seg {
Prior complexity(double per_segment, double per_metre);
}  // namespace seg

// ---- likelihood ------------------------------------------------------------------------------
struct PointsGaussian {
  LikelihoodParams params;
};
using Likelihood = std::variant<PointsGaussian>;
namespace points {
Likelihood gaussian(double sigma, double background);
}  // namespace points

// ---- proposal sources ------------------------------------------------------------------------
struct Ransac {  // detect.ransac: makes birth / death
  RansacParams ransac;
  BirthParams birth;
};
struct PoorSupport {  // support.poor: serves death
  DeathParams death;
};
struct Gaps {  // detect.gaps: makes split / merge
  SplitParams split;
};
struct InverseGap {  // partner.inverse_gap: serves merge
  MergeParams merge;
};
struct EndpointJitter {  // move.endpoint_jitter: makes jitter
  JitterParams jitter;
};
using Source = std::variant<Ransac, PoorSupport, Gaps, InverseGap, EndpointJitter>;
namespace detect {
Source ransac(int min_inliers, double inlier_dist, int candidates, double max_gap, double jitter, double power);
Source gaps(double bin, double gap_weight, double jitter, double near);
}  // namespace detect
namespace support {
Source poor(double explain);
}  // namespace support
namespace partner {
Source inverse_gap(double eps, double angle_scale);
}  // namespace partner
namespace move {
// shift_prob + slide_prob above 1 are scaled to sum 1 (no move of one endpoint alone).
Source endpoint_jitter(double sigma, double shift_prob, double slide, double slide_prob);
}  // namespace move

// The kit declares no `extern output`.
struct Output {};

using Binding = runtime::domain::Binding<Scene, Prior, Likelihood, Move, Source, Output>;

}  // namespace ksmc::stdlib::segments::blocks
