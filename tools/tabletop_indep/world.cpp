#include "tools/tabletop_indep/world.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace ksmc::tools::tabletop_indep {

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
int uniform_int(Rng& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
bool chance(Rng& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }

namespace {

constexpr double kClearance = 0.012;  // m between boxes that do not touch
constexpr double kTouch = 0.0005;     // m of overlap allowed where boxes touch by construction

double log_uniform(Rng& rng, double lo, double hi) { return std::exp(uniform(rng, std::log(lo), std::log(hi))); }

// Extent of a box along a horizontal unit direction.
double half_along(const Obb& b, const Eigen::Vector3d& u) { return (b.rot.transpose() * u).cwiseAbs().dot(b.half()); }

// The face a box of `size` rests on: mostly its largest face, sometimes another one that
// still stands (height at most 2.5 times the smaller footprint side).
int rest_axis(Rng& rng, const Eigen::Vector3d& size) {
  int shortest = 0;
  for (int i = 1; i < 3; ++i)
    if (size[i] < size[shortest]) shortest = i;
  if (chance(rng, 0.6)) return shortest;
  const int k = uniform_int(rng, 0, 2);
  const double foot = std::min(size[(k + 1) % 3], size[(k + 2) % 3]);
  return size[k] <= 2.5 * foot ? k : shortest;
}

bool clear_of(const World& w, const Obb& b, std::initializer_list<int> except) {
  for (int i = 0; i < static_cast<int>(w.bodies.size()); ++i) {
    if (std::find(except.begin(), except.end(), i) != except.end()) continue;
    if (penetration(w.bodies[static_cast<std::size_t>(i)].box, b) > -kClearance) return false;
  }
  return true;
}

bool in_region(const Obb& b, const WorldOptions& o) {
  for (const auto& c : b.corners())
    if (std::abs(c.x()) > o.region_x || std::abs(c.y()) > o.region_y) return false;
  return true;
}

// A random body among those `keep` accepts, or nullopt.
template <typename Keep>
std::optional<int> pick_body(Rng& rng, const World& w, Keep keep) {
  std::vector<int> found;
  for (int i = 0; i < static_cast<int>(w.bodies.size()); ++i)
    if (keep(i, w.bodies[static_cast<std::size_t>(i)])) found.push_back(i);
  if (found.empty()) return std::nullopt;
  return found[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(found.size()) - 1))];
}

bool on_the_table(const Body& b) { return b.rests_on.size() == 1 && b.rests_on[0] == kTable; }

double yaw_of(const Obb& b) {
  const Eigen::Vector3d x = b.rot.col((b.up_axis() + 1) % 3);
  return std::atan2(x.y(), x.x());
}

std::optional<Body> on_table(Rng& rng, const World& w, const WorldOptions& o, bool flush) {
  Body body;
  body.box.size = draw_size(rng, o.catalogue, body.label);
  const int axis = rest_axis(rng, body.box.size);
  const std::optional<int> neighbour = flush ? pick_body(rng, w, [](int, const Body& b) { return on_the_table(b); }) : std::nullopt;
  if (neighbour) {
    const int g = *neighbour;
    const Obb& n = w.bodies[static_cast<std::size_t>(g)].box;
    body.box.rot = resting_rotation(axis, chance(rng, 0.5), yaw_of(n) + 0.5 * std::numbers::pi * uniform_int(rng, 0, 3));
    const int side = (n.up_axis() + uniform_int(rng, 1, 2)) % 3;
    const Eigen::Vector3d u = (chance(rng, 0.5) ? 1.0 : -1.0) * n.rot.col(side);
    const Eigen::Vector3d v = Eigen::Vector3d::UnitZ().cross(u);
    const double slide = half_along(n, v) + 0.5 * half_along(body.box, v);
    body.box.centre = n.centre + (half_along(n, u) + half_along(body.box, u)) * u + uniform(rng, -slide, slide) * v;
    body.box.centre.z() = 0.5 * (body.box.top() - body.box.bottom());
    if (!clear_of(w, body.box, {g}) || penetration(n, body.box) > kTouch || !in_region(body.box, o)) return std::nullopt;
    body.rests_on = {kTable};
    return body;
  }
  body.box.rot = resting_rotation(axis, chance(rng, 0.5), uniform(rng, -std::numbers::pi, std::numbers::pi));
  body.box.centre = Eigen::Vector3d(uniform(rng, -o.region_x, o.region_x), uniform(rng, -o.region_y, o.region_y), 0.0);
  body.box.centre.z() = -body.box.bottom();
  if (!clear_of(w, body.box, {}) || !in_region(body.box, o)) return std::nullopt;
  body.rests_on = {kTable};
  return body;
}

std::optional<Body> on_box(Rng& rng, const World& w, const WorldOptions& o) {
  const std::optional<int> supporter =
      pick_body(rng, w, [](int, const Body& b) { return !b.rests_on.empty() && b.box.top() < 0.45; });
  if (!supporter) return std::nullopt;
  const int s = *supporter;
  const Obb& lower = w.bodies[static_cast<std::size_t>(s)].box;
  Body body;
  body.box.size = draw_size(rng, o.catalogue, body.label);
  const int axis = rest_axis(rng, body.box.size);
  const double yaw = chance(rng, 0.5) ? yaw_of(lower) + 0.5 * std::numbers::pi * uniform_int(rng, 0, 3)
                                      : uniform(rng, -std::numbers::pi, std::numbers::pi);
  body.box.rot = resting_rotation(axis, chance(rng, 0.5), yaw);
  // The centre of mass over the supporter's top, 5 mm in from its edges: statically stable.
  const int up = lower.up_axis();
  Eigen::Vector3d local = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i)
    if (i != up) local[i] = uniform(rng, -1.0, 1.0) * std::max(0.0, 0.5 * lower.size[i] - 0.005);
  body.box.centre = lower.centre + lower.rot * local;
  body.box.centre.z() = lower.top() + 0.5 * (body.box.top() - body.box.bottom());
  if (!over_top(lower, body.box.centre.head<2>(), 0.004)) return std::nullopt;
  if (footprint_overlap(body.box, lower) < 4e-4) return std::nullopt;  // 2 cm x 2 cm at least
  if (!clear_of(w, body.box, {s}) || penetration(lower, body.box) > kTouch || !in_region(body.box, o)) return std::nullopt;
  body.rests_on = {s};
  return body;
}

std::optional<Body> leaning(Rng& rng, const World& w, const WorldOptions& o) {
  const std::optional<int> wall_index =
      pick_body(rng, w, [](int, const Body& b) { return on_the_table(b) && b.box.top() >= 0.07; });
  if (!wall_index) return std::nullopt;
  const int wi = *wall_index;
  const Obb& wall = w.bodies[static_cast<std::size_t>(wi)].box;
  const int side = (wall.up_axis() + uniform_int(rng, 1, 2)) % 3;
  const Eigen::Vector3d u = (chance(rng, 0.5) ? 1.0 : -1.0) * wall.rot.col(side);  // out of the wall's face
  const Eigen::Vector3d v = Eigen::Vector3d::UnitZ().cross(u);
  const double face_width = 2.0 * half_along(wall, v);
  const double theta = uniform(rng, 10.0, 35.0) * std::numbers::pi / 180.0;
  const double thick = log_uniform(rng, 0.01, 0.04);
  const double h_max = (wall.top() - 0.006 - thick * std::sin(theta)) / std::cos(theta);
  if (h_max < 0.05) return std::nullopt;
  const double depth = std::min(face_width + 0.02, log_uniform(rng, 0.04, 0.2));
  Body body;
  body.label = "leaner";
  body.box.size = Eigen::Vector3d(thick, depth, uniform(rng, std::max(0.05, 0.5 * h_max), h_max));
  // It rests on its bottom edge nearer the wall; it leans (rather than falling back onto its
  // face) only with its centre of mass on the wall's side of that edge, here by 8 mm at least.
  if (0.5 * (body.box.size.z() * std::sin(theta) - thick * std::cos(theta)) < 0.008) return std::nullopt;
  Eigen::Matrix3d frame;
  frame << u, v, Eigen::Vector3d::UnitZ();
  // Tilted about v so that its top goes towards the wall (-u).
  body.box.rot = frame * Eigen::AngleAxisd(-theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
  body.box.centre = Eigen::Vector3d::Zero();
  const auto corners = body.box.corners();
  double min_z = 1e9, min_u = 1e9;
  Eigen::Vector3d touching = Eigen::Vector3d::Zero();
  for (const auto& c : corners) {
    min_z = std::min(min_z, c.z());
    if (c.dot(u) < min_u) {
      min_u = c.dot(u);
      touching = c;
    }
  }
  const double slide = std::max(0.0, 0.5 * face_width - 0.5 * depth);
  const double face = wall.centre.dot(u) + half_along(wall, u);
  body.box.centre = (face - min_u) * u + (wall.centre.dot(v) + uniform(rng, -slide, slide)) * v;
  body.box.centre.z() = -min_z;
  if (touching.z() - min_z >= wall.top() - 0.005) return std::nullopt;
  if (!clear_of(w, body.box, {wi}) || penetration(wall, body.box) > kTouch || !in_region(body.box, o)) return std::nullopt;
  body.leans_on = wi;
  return body;
}

}  // namespace

Eigen::Vector3d draw_size(Rng& rng, Catalogue catalogue, std::string& label) {
  // household: cartons, tins and packets; wide adds cubes, boards and bars from 2 to 40 cm.
  const int kind = catalogue == Catalogue::household ? 0 : uniform_int(rng, 0, 3);
  Eigen::Vector3d s;
  switch (kind) {
    case 1: {
      label = "cube";
      const double a = log_uniform(rng, 0.02, 0.3);
      s = Eigen::Vector3d(a, a, a).cwiseProduct(Eigen::Vector3d(uniform(rng, 0.95, 1.05), uniform(rng, 0.95, 1.05), 1.0));
      break;
    }
    case 2: {
      label = "board";
      const double l = log_uniform(rng, 0.1, 0.4);
      s = Eigen::Vector3d(l, uniform(rng, 0.4, 1.0) * l, log_uniform(rng, 0.01, 0.02));
      break;
    }
    case 3: {
      label = "bar";
      const double t = log_uniform(rng, 0.02, 0.05);
      s = Eigen::Vector3d(log_uniform(rng, 0.15, 0.4), t, t * uniform(rng, 0.8, 1.2));
      break;
    }
    default: {
      label = "carton";
      const double l = log_uniform(rng, 0.06, 0.25);
      const double m = l * uniform(rng, 0.35, 1.0);
      s = Eigen::Vector3d(l, m, std::max(0.02, m * uniform(rng, 0.25, 1.0)));
    }
  }
  // Shuffle the axes: the catalogue's x is not the long side.
  std::array<int, 3> p{0, 1, 2};
  std::shuffle(p.begin(), p.end(), rng);
  return Eigen::Vector3d(s[p[0]], s[p[1]], s[p[2]]);
}

bool World::carries_something(int i) const {
  for (const auto& b : bodies) {
    if (b.leans_on == i || std::find(b.rests_on.begin(), b.rests_on.end(), i) != b.rests_on.end()) return true;
  }
  return false;
}

bool World::hidden(int i) const {
  const Body& b = bodies[static_cast<std::size_t>(i)];
  if (b.undetected || b.rests_on.empty()) return false;
  return std::all_of(b.rests_on.begin(), b.rests_on.end(),
                     [&](int s) { return s != kTable && bodies[static_cast<std::size_t>(s)].undetected; });
}

World build_world(Rng& rng, const WorldOptions& o) {
  World w;
  const int n = uniform_int(rng, o.min_boxes, o.max_boxes);
  for (int k = 0; k < n; ++k) {
    const double role = uniform(rng, 0.0, 1.0);
    for (int attempt = 0; attempt < 40; ++attempt) {
      std::optional<Body> b;
      if (k > 0 && role < o.stack_rate) b = on_box(rng, w, o);
      else if (k > 0 && role < o.stack_rate + o.lean_rate) b = leaning(rng, w, o);
      else b = on_table(rng, w, o, chance(rng, o.flush_rate));
      if (!b) continue;
      const int id = static_cast<int>(w.bodies.size());
      if (b->leans_on >= 0) {
        w.contact.emplace_back(id, kTable);
        w.contact.emplace_back(b->leans_on, id);
      } else if (on_the_table(*b)) {
        for (int j = 0; j < id; ++j)  // flush placement: the one neighbour it touches
          if (penetration(w.bodies[static_cast<std::size_t>(j)].box, b->box) > -0.001) w.contact.emplace_back(j, id);
      }
      w.bodies.push_back(std::move(*b));
      break;
    }
  }
  // Undetected supporters: a box that carries boxes (and has no box leaning on it) and stands
  // at least 2.5 cm tall, so that what it carries visibly hovers.
  for (int h = 0; h < o.max_hidden && chance(rng, o.hidden_rate); ++h) {
    const std::optional<int> carrier = pick_body(rng, w, [&](int i, const Body& b) {
      if (b.undetected || b.box.top() < 0.025 || !w.carries_something(i)) return false;
      return std::none_of(w.bodies.begin(), w.bodies.end(), [&](const Body& other) { return other.leans_on == i; });
    });
    if (!carrier) break;
    w.bodies[static_cast<std::size_t>(*carrier)].undetected = true;
  }
  return w;
}

}  // namespace ksmc::tools::tabletop_indep
