#include "stdlib/segments/blocks.h"

namespace ksmc::stdlib::segments::blocks {

namespace seg {
bool touching(const Scene&, const Segment& a, const Segment& b, double gap) { return segments::touching(a, b, gap); }
bool perpendicular(const Scene&, const Segment& a, const Segment& b, double tol) {
  return segments::perpendicular(a, b, tol);
}
bool parallel(const Scene&, const Segment& a, const Segment& b, double tol) { return segments::parallel(a, b, tol); }
bool close(const Scene&, const Segment& a, const Segment& b, double dist) { return close_lines(a, b, dist); }
bool short_(const Scene&, const Segment& a, double max_length) { return is_short(a, max_length); }
Prior complexity(double per_segment, double per_metre) { return Complexity{per_segment, per_metre}; }
}  // namespace seg

double endpoint_gap(const Scene&, const Segment& a, const Segment& b) { return segments::endpoint_gap(a, b); }
double line_offset(const Scene&, const Segment& a, const Segment& b) { return segments::line_offset(a, b); }
double corner_angle_error(const Scene&, const Segment& a, const Segment& b) { return segments::corner_angle_error(a, b); }
double parallel_angle_error(const Scene&, const Segment& a, const Segment& b) {
  return segments::parallel_angle_error(a, b);
}

double gaussian(const Scene&, double x, double sigma) {
  const double z = x / sigma;
  return -0.5 * z * z;
}
double gaussian_angle(const Scene& s, double x, double sigma) { return gaussian(s, x, sigma); }

Prior mln() { return MlnPrior{}; }

namespace points {
Likelihood gaussian(double sigma, double background) { return PointsGaussian{{sigma, background}}; }
}  // namespace points

namespace detect {
Source ransac(int min_inliers, double inlier_dist, int candidates, double max_gap, double jitter, double power) {
  Ransac r;
  r.ransac = {min_inliers, inlier_dist, candidates, max_gap};
  r.birth = {jitter, power, inlier_dist};  // a point within the inlier distance is explained
  return r;
}
Source gaps(double bin, double gap_weight, double jitter, double near) { return Gaps{{bin, gap_weight, jitter, near}}; }
}  // namespace detect

namespace support {
Source poor(double explain) { return PoorSupport{{explain}}; }
}  // namespace support

namespace partner {
Source inverse_gap(double eps, double angle_scale) { return InverseGap{{eps, angle_scale}}; }
}  // namespace partner

namespace move {
Source endpoint_jitter(double sigma, double shift_prob, double slide, double slide_prob) {
  const double sum = shift_prob + slide_prob;
  if (sum > 1.0) {
    shift_prob /= sum;
    slide_prob = 1.0 - shift_prob;
  }
  return EndpointJitter{{sigma, shift_prob, slide, slide_prob}};
}
}  // namespace move

}  // namespace ksmc::stdlib::segments::blocks
