// Internal to the kernels: shared context, per-kernel entry points and weightings.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "stdlib/indoor/geometry.h"
#include "stdlib/indoor/kernels.h"

namespace ksmc::stdlib::indoor::kernels {

struct Context {
  const MapEvidence& ev;
  const KernelSources& src;
  const KernelParams& p;
};

// A forward proposal before its reverse probability is known.
struct Forward {
  Move move;
  double log_q = 0.0;
};

// Per kernel pair: propose (forward choices and their log probability) and log_q (probability
// of proposing a given move). `kind` selects the member of a pair where both share code.
std::optional<Forward> propose_add(const Context& c, const World& w, Rng& rng);
double log_q_add(const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_remove(const Context& c, const World& w, Rng& rng);
double log_q_remove(const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_split(const Context& c, const World& w, Rng& rng);
double log_q_split(const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_merge(const Context& c, const World& w, Rng& rng);
double log_q_merge(const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_shift(KernelKind kind, const Context& c, const World& w, Rng& rng);
double log_q_shift(KernelKind kind, const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_allocate(const Context& c, const World& w, Rng& rng);
double log_q_allocate(const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_delete(const Context& c, const World& w, Rng& rng);
double log_q_delete(const Context& c, const World& w, const Move& m);
std::optional<Forward> propose_interchange(const Context& c, const World& w, Rng& rng);
double log_q_interchange(const Context& c, const World& w, const Move& m);

// b_r (eq. 3.21) of every unit of w, in w.units() order.
std::vector<double> unit_change_weights(const Context& c, const World& w);
// v_w (eq. 3.22) of the four walls of u.
std::array<double, 4> wall_change_weights(const Context& c, const Unit& u);
// log probability that the pair {r, s} is drawn as (first uniform, second by inverse centre
// distance, eq. 3.19-3.20 / 3.26-3.27) in either order; -inf if either is absent.
double log_pair_probability(const World& w, UnitId r, UnitId s);
// Draws (first, second) as above; nullopt with fewer than two units.
std::optional<std::pair<std::size_t, std::size_t>> draw_pair(const World& w, Rng& rng);
// Index of the unit with this id in w.units(), or nullopt.
std::optional<std::size_t> unit_index(const World& w, UnitId id);
// True when the unit exists, its rect matches `r` and it carries no door.
bool unit_free(const Context& c, const World& w, UnitId id, const OrientedRect& r);
// True when the unit exists and its rect matches `r` (doors allowed).
bool unit_matches(const Context& c, const World& w, UnitId id, const OrientedRect& r);
// Distance (cells) from the midpoint of segment a-b to the nearest wall of `r` parallel to it
// (within door_angle) whose extent contains the midpoint; +inf when there is none. A door
// lies on a unit's wall when this is at most door_snap (the rule ALLOCATE attaches by).
double door_wall_distance(const Context& c, const OrientedRect& r, Point2 a, Point2 b);

// Move shape checks: unit changes of the form (removed, added, modified) counts.
struct Shape {
  std::vector<const UnitChange*> removed, added, modified;
};
Shape shape_of(const Move& m);

double log_normal_pdf(double x, double sigma);

// Segments a-b and p-q coincide (either direction) within KernelParams::coincide.
bool same_segment(const Context& c, Point2 a, Point2 b, Point2 p, Point2 q);

}  // namespace ksmc::stdlib::indoor::kernels
