// 2D geometry of line segments: points, segments with a canonical endpoint order, distances
// and angles, and the relations the evidence extractors of stdlib/segments.ksm test.
#pragma once

#include <array>
#include <cmath>

namespace ksmc::stdlib::segments {

inline constexpr double kPi = 3.14159265358979323846;

struct Vec2 {
  double x = 0.0, y = 0.0;
  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }
inline double dist(Vec2 a, Vec2 b) { return norm(a - b); }

// A segment between two endpoints. The model keeps every segment canonical (a before b in
// (x, y) lexicographic order), so a segment and its reversal are the same state.
struct Segment {
  Vec2 a, b;
  double length() const { return dist(a, b); }
  Vec2 mid() const { return 0.5 * (a + b); }
  friend bool operator==(const Segment& s, const Segment& t) { return s.a == t.a && s.b == t.b; }
};

// The segment with its endpoints in canonical order.
Segment canonical(Vec2 p, Vec2 q);
// Unit direction from a to b ((1, 0) for a zero-length segment).
Vec2 direction(const Segment& s);
// Euclidean distance from p to the closed segment.
double point_segment_distance(Vec2 p, const Segment& s);
// Distance from p to the infinite line through the segment (to a for a zero-length one).
double point_line_distance(Vec2 p, const Segment& s);
// Parameter t of p's projection on the line a + t (b - a) (0 for a zero-length segment).
double projection_param(Vec2 p, const Segment& s);
// Undirected angle between the segments' lines, in [0, pi/2].
double undirected_angle(const Segment& s, const Segment& t);

// Functions of stdlib/segments.ksm.
double endpoint_gap(const Segment& s, const Segment& t);        // closest endpoints, metres
double line_offset(const Segment& s, const Segment& t);         // mean midpoint-to-other-line, metres
double corner_angle_error(const Segment& s, const Segment& t);  // |angle - 90 deg|, radians
double parallel_angle_error(const Segment& s, const Segment& t);  // angle, radians

// Extractors of stdlib/segments.ksm (parameters in metres / radians).
bool touching(const Segment& s, const Segment& t, double gap);
bool perpendicular(const Segment& s, const Segment& t, double tol);
bool parallel(const Segment& s, const Segment& t, double tol);
bool close_lines(const Segment& s, const Segment& t, double max_dist);
bool is_short(const Segment& s, double max_length);

}  // namespace ksmc::stdlib::segments
