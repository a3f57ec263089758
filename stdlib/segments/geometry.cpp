#include "stdlib/segments/geometry.h"

#include <algorithm>

namespace ksmc::stdlib::segments {

Segment canonical(Vec2 p, Vec2 q) {
  if (q.x < p.x || (q.x == p.x && q.y < p.y)) return {q, p};
  return {p, q};
}

Vec2 direction(const Segment& s) {
  const Vec2 d = s.b - s.a;
  const double n = norm(d);
  if (!(n > 0.0)) return {1.0, 0.0};
  return (1.0 / n) * d;
}

double projection_param(Vec2 p, const Segment& s) {
  const Vec2 d = s.b - s.a;
  const double l2 = dot(d, d);
  if (!(l2 > 0.0)) return 0.0;
  return dot(p - s.a, d) / l2;
}

double point_segment_distance(Vec2 p, const Segment& s) {
  const double t = std::clamp(projection_param(p, s), 0.0, 1.0);
  return dist(p, s.a + t * (s.b - s.a));
}

double point_line_distance(Vec2 p, const Segment& s) {
  if (!(s.length() > 0.0)) return dist(p, s.a);
  return std::abs(cross(direction(s), p - s.a));
}

double undirected_angle(const Segment& s, const Segment& t) {
  const Vec2 u = direction(s), v = direction(t);
  const double c = std::min(1.0, std::abs(dot(u, v)));
  const double sn = std::min(1.0, std::abs(cross(u, v)));
  return std::atan2(sn, c);  // in [0, pi/2]
}

double endpoint_gap(const Segment& s, const Segment& t) {
  return std::min({dist(s.a, t.a), dist(s.a, t.b), dist(s.b, t.a), dist(s.b, t.b)});
}

double line_offset(const Segment& s, const Segment& t) {
  return 0.5 * (point_line_distance(t.mid(), s) + point_line_distance(s.mid(), t));
}

double corner_angle_error(const Segment& s, const Segment& t) { return 0.5 * kPi - undirected_angle(s, t); }

double parallel_angle_error(const Segment& s, const Segment& t) { return undirected_angle(s, t); }

bool touching(const Segment& s, const Segment& t, double gap) { return endpoint_gap(s, t) <= gap; }

bool perpendicular(const Segment& s, const Segment& t, double tol) { return corner_angle_error(s, t) <= tol; }

bool parallel(const Segment& s, const Segment& t, double tol) { return parallel_angle_error(s, t) <= tol; }

bool close_lines(const Segment& s, const Segment& t, double max_dist) {
  return point_line_distance(t.mid(), s) <= max_dist && point_line_distance(s.mid(), t) <= max_dist;
}

bool is_short(const Segment& s, double max_length) { return s.length() < max_length; }

}  // namespace ksmc::stdlib::segments
