#include "tools/tabletop_indep/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

namespace ksmc::tools::tabletop_indep {

const char* to_string(FalseKind k) {
  switch (k) {
    case FalseKind::none: return "none";
    case FalseKind::floating: return "floating";
    case FalseKind::intersecting: return "intersecting";
    case FalseKind::shifted_copy: return "shifted_copy";
    case FalseKind::duplicate: return "duplicate";
    case FalseKind::wrong_size: return "wrong_size";
    case FalseKind::flipped: return "flipped";
    case FalseKind::tilted: return "tilted";
  }
  return "?";
}

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Matrix3d about(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

Eigen::Vector3d random_unit(Rng& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Vector3d v(n(rng), n(rng), n(rng));
  return v.norm() < 1e-9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(v.normalized());
}

Eigen::Vector3d random_horizontal(Rng& rng) {
  const double a = uniform(rng, -std::numbers::pi, std::numbers::pi);
  return {std::cos(a), std::sin(a), 0.0};
}

// `b` moved along `dir` until it overlaps `target` by `depth` (bisection on the SAT depth).
std::optional<Obb> pushed_into(Obb b, const Obb& target, const Eigen::Vector3d& dir, double depth) {
  const Eigen::Vector3d start = b.centre;
  auto at = [&](double s) {
    b.centre = start + s * dir;
    return penetration(b, target);
  };
  double lo = 0.0, hi = b.size.norm() + target.size.norm();
  if (at(lo) < depth || at(hi) >= depth) return std::nullopt;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (at(mid) >= depth ? lo : hi) = mid;
  }
  at(lo);
  return b;
}

double vertical_extent(const Obb& b) { return b.top() - b.bottom(); }

struct Builder {
  Rng& rng;
  const ObserveOptions& o;
  IndepScene s;

  bool clear_of_world(const Obb& b, double gap) const {
    for (const auto& body : s.world.bodies)
      if (penetration(body.box, b) > -gap) return false;
    for (const auto& e : s.estimates)
      if (e.kind != FalseKind::none && penetration(e.clean, b) > -gap) return false;
    return true;
  }

  std::optional<Obb> floating_box() {
    for (int attempt = 0; attempt < 30; ++attempt) {
      std::string label;
      Obb b;
      b.size = draw_size(rng, Catalogue::household, label);
      b.rot = about(random_horizontal(rng), uniform(rng, 0.0, 40.0) * kDeg) *
              resting_rotation(uniform_int(rng, 0, 2), chance(rng, 0.5), uniform(rng, -3.2, 3.2));
      const Obb& near = s.world.bodies[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(s.world.bodies.size()) - 1))].box;
      b.centre = near.centre + Eigen::Vector3d(uniform(rng, -0.2, 0.2), uniform(rng, -0.2, 0.2), 0.0);
      b.centre.z() = 0.0;
      b.centre.z() = uniform(rng, 0.015, 0.15) - b.bottom();
      if (clear_of_world(b, 0.015)) return b;
    }
    return std::nullopt;
  }

  std::optional<Obb> intersecting_box(const Obb& target) {
    std::string label;
    Obb b;
    b.size = draw_size(rng, Catalogue::household, label);
    b.rot = resting_rotation(uniform_int(rng, 0, 2), chance(rng, 0.5), uniform(rng, -3.2, 3.2));
    b.centre = target.centre;
    if (chance(rng, 0.5)) b.centre.z() = 0.5 * vertical_extent(b);  // stands on the table
    return pushed_into(b, target, random_horizontal(rng), uniform(rng, 0.015, 0.05));
  }

  std::optional<Obb> modified(const Obb& clean, FalseKind kind) {
    Obb b = clean;
    const int up = clean.up_axis();
    switch (kind) {
      case FalseKind::shifted_copy: return pushed_into(b, clean, random_horizontal(rng), uniform(rng, 0.015, 0.05));
      case FalseKind::duplicate:
        b.centre += uniform(rng, 0.005, 0.025) * random_unit(rng);
        b.rot = about(random_unit(rng), uniform(rng, 4.0, 15.0) * kDeg) * b.rot;
        b.centre.z() += std::max(0.0, -0.004 - b.bottom());
        return b;
      case FalseKind::wrong_size:
        b.size[up] *= chance(rng, 0.5) ? uniform(rng, 0.5, 0.75) : uniform(rng, 1.3, 1.8);
        if (chance(rng, 0.5)) b.size[(up + uniform_int(rng, 1, 2)) % 3] *= uniform(rng, 0.7, 1.4);
        if (std::abs(b.size[up] - clean.size[up]) < 0.016) return std::nullopt;
        return b;
      case FalseKind::flipped:
        b.rot = about(clean.rot.col((up + uniform_int(rng, 1, 2)) % 3), 0.5 * std::numbers::pi) * clean.rot;
        if (std::abs(vertical_extent(b) - vertical_extent(clean)) < 0.016) return std::nullopt;
        return b;
      case FalseKind::tilted:
        b.rot = about(random_horizontal(rng), uniform(rng, 12.0, 35.0) * kDeg) * clean.rot;
        return b;
      default: return std::nullopt;
    }
  }

  // Bodies whose estimate may itself be wrong: detected, standing, carrying nothing, not hidden.
  bool modifiable(int i) const {
    const Body& b = s.world.bodies[static_cast<std::size_t>(i)];
    return !b.undetected && !b.rests_on.empty() && !s.world.carries_something(i) && !s.world.hidden(i);
  }

  void add_false_estimates() {
    const std::size_t real = s.estimates.size();
    std::discrete_distribution<int> pick_kind(o.false_odds.begin(), o.false_odds.end());
    for (std::size_t k = 0; k < real; ++k) {
      if (!chance(rng, o.false_rate)) continue;
      const FalseKind kind = kFalseKinds[static_cast<std::size_t>(pick_kind(rng))];
      Estimate& target = s.estimates[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(real) - 1))];
      std::optional<Obb> box;
      if (kind == FalseKind::wrong_size || kind == FalseKind::flipped || kind == FalseKind::tilted) {
        if (target.kind != FalseKind::none || !modifiable(target.body)) continue;
        box = modified(target.clean, kind);
        if (!box) continue;
        target.kind = kind;
        target.clean = *box;
        continue;
      }
      if (kind == FalseKind::floating) box = floating_box();
      else if (kind == FalseKind::intersecting) box = intersecting_box(target.clean);
      else box = modified(s.world.bodies[static_cast<std::size_t>(target.body)].box, kind);
      if (!box) continue;
      Estimate e;
      e.kind = kind;
      e.clean = *box;
      s.estimates.push_back(std::move(e));
    }
  }

  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d c = s.camera.rot.transpose() * (p - s.camera.eye);
    if (c.z() < 0.05) return std::nullopt;
    return Eigen::Vector2d(s.camera.fx * c.x() / c.z() + s.camera.cx, s.camera.fy * c.y() / c.z() + s.camera.cy);
  }

  bool in_image(const Eigen::Vector2d& uv, double border) const {
    return uv.x() >= border && uv.y() >= border && uv.x() <= s.camera.width - border && uv.y() <= s.camera.height - border;
  }

  bool place_camera() {
    Camera& c = s.camera;
    const bool hd = chance(rng, 0.4);
    c.width = hd ? 1280 : 640;
    c.height = hd ? 720 : 480;
    c.fx = c.width * uniform(rng, 0.85, 1.45);
    c.fy = c.fx * uniform(rng, 0.995, 1.005);
    c.cx = 0.5 * c.width + uniform(rng, -8.0, 8.0);
    c.cy = 0.5 * c.height + uniform(rng, -6.0, 6.0);
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    for (const auto& b : s.world.bodies) target += b.box.centre;
    target /= static_cast<double>(s.world.bodies.size());
    target += Eigen::Vector3d(uniform(rng, -0.03, 0.03), uniform(rng, -0.03, 0.03), 0.0);
    target.z() = 0.0;
    const double az = uniform(rng, -std::numbers::pi, std::numbers::pi);
    const double el = uniform(rng, o.min_elevation, o.max_elevation) * kDeg;
    double dist = uniform(rng, o.min_distance, o.max_distance);
    const Eigen::Vector3d dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const Eigen::Vector3d forward = -dir;
    const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d down = forward.cross(right);
    c.rot << right, down, forward;
    for (int step = 0; step < 12; ++step, dist *= 1.12) {
      c.eye = target + dist * dir;
      bool all = true;
      for (const auto& e : s.estimates) {
        for (const auto& corner : e.clean.corners()) {
          const auto uv = project(corner);
          all = all && uv && in_image(*uv, 4.0);
        }
      }
      if (all) return true;
    }
    return false;
  }

  void add_noise(Estimate& e) {
    std::student_t_distribution<double> t5(5.0);
    const double unit = std::sqrt(3.0 / 5.0);  // t(5) has variance 5/3
    const Eigen::Vector3d ray = (e.clean.centre - s.camera.eye).normalized();
    const Eigen::Vector3d side = ray.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d up = side.cross(ray);
    e.noisy = e.clean;
    e.noisy.centre += o.sigma_t * unit * (t5(rng) * side + t5(rng) * up + o.depth_factor * t5(rng) * ray);
    std::normal_distribution<double> n(0.0, o.sigma_r * kDeg);
    const Eigen::Vector3d w = s.camera.rot * Eigen::Vector3d(n(rng), n(rng), n(rng));
    if (w.norm() > 1e-12) e.noisy.rot = about(w, w.norm()) * e.clean.rot;
  }

  bool occluded(const Eigen::Vector3d& p, int own_body) const {
    const Eigen::Vector3d d = p - s.camera.eye;
    for (int i = 0; i < static_cast<int>(s.world.bodies.size()); ++i) {
      if (i == own_body) continue;
      const Obb& b = s.world.bodies[static_cast<std::size_t>(i)].box;
      const Eigen::Vector3d o0 = b.rot.transpose() * (s.camera.eye - b.centre);
      const Eigen::Vector3d dd = b.rot.transpose() * d;
      double lo = 0.0, hi = 1.0 - 1e-6;
      bool hit = true;
      for (int k = 0; k < 3 && hit; ++k) {
        const double h = 0.5 * b.size[k] - 0.001;
        if (std::abs(dd[k]) < 1e-12) {
          hit = std::abs(o0[k]) <= h;
          continue;
        }
        double t1 = (-h - o0[k]) / dd[k], t2 = (h - o0[k]) / dd[k];
        if (t1 > t2) std::swap(t1, t2);
        lo = std::max(lo, t1);
        hi = std::min(hi, t2);
        hit = lo <= hi;
      }
      if (hit) return true;
    }
    return false;
  }

  void add_keypoints(Estimate& e) {
    const Obb& b = e.clean;
    struct Face {
      int axis;
      double sign;
    };
    std::vector<Face> faces;
    std::vector<double> weights;
    for (int axis = 0; axis < 3; ++axis) {
      for (double sign : {-1.0, 1.0}) {
        const Eigen::Vector3d normal = sign * b.rot.col(axis);
        const Eigen::Vector3d centre = b.centre + 0.5 * b.size[axis] * normal;
        const double cosine = normal.dot((s.camera.eye - centre).normalized());
        if (cosine < 0.15) continue;
        faces.push_back({axis, sign});
        weights.push_back(cosine * b.size.prod() / b.size[axis]);
      }
    }
    if (faces.empty()) return;
    std::discrete_distribution<int> pick(weights.begin(), weights.end());
    std::normal_distribution<double> px(0.0, o.pixel_sigma);
    const int wanted = static_cast<int>(std::lround(
        std::exp(uniform(rng, std::log(o.min_keypoints), std::log(o.max_keypoints + 0.999)))));
    for (int attempt = 0; attempt < 8 * wanted && static_cast<int>(e.kp_model.size()) < wanted; ++attempt) {
      const Face& f = faces[static_cast<std::size_t>(pick(rng))];
      Eigen::Vector3d local;
      for (int k = 0; k < 3; ++k) local[k] = uniform(rng, -0.5, 0.5) * b.size[k];
      local[f.axis] = f.sign * 0.5 * b.size[f.axis];
      const Eigen::Vector3d p = b.centre + b.rot * local;
      if (occluded(p, e.body)) continue;
      auto uv = project(p);
      if (!uv) continue;
      *uv += Eigen::Vector2d(px(rng), px(rng));
      if (chance(rng, o.outlier_rate)) {
        const double a = uniform(rng, -std::numbers::pi, std::numbers::pi);
        *uv += uniform(rng, 15.0, 80.0) * Eigen::Vector2d(std::cos(a), std::sin(a));
      }
      if (!in_image(*uv, 0.0)) continue;
      e.kp_model.push_back(local);
      e.kp_image.push_back(*uv);
    }
  }

  void assign_ids() {
    std::shuffle(s.estimates.begin(), s.estimates.end(), rng);
    // Distinct ids drawn from 1..998 (or more, should a scene hold more estimates).
    std::vector<int> numbers(std::max<std::size_t>(998, s.estimates.size()));
    for (std::size_t i = 0; i < numbers.size(); ++i) numbers[i] = static_cast<int>(i) + 1;
    std::shuffle(numbers.begin(), numbers.end(), rng);
    for (std::size_t i = 0; i < s.estimates.size(); ++i)
      s.estimates[i].id = o.numeric_ids ? std::to_string(numbers[i]) : fmt::format("obj{}", numbers[i]);
  }
};

std::string num(double v, int decimals) {
  std::string t = fmt::format("{:.{}f}", v, decimals);
  if (t.find_first_not_of("-0.") == std::string::npos && t.front() == '-') t.erase(0, 1);
  return t;
}

std::string pose_json(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
  Eigen::Quaterniond q(r);
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;
  return fmt::format(R"({{"t": [{}, {}, {}], "q": [{}, {}, {}, {}]}})", num(t.x(), 6), num(t.y(), 6), num(t.z(), 6),
                     num(q.w(), 9), num(q.x(), 9), num(q.y(), 9), num(q.z(), 9));
}

}  // namespace

std::optional<IndepScene> observe(Rng& rng, World world, const ObserveOptions& options) {
  if (world.bodies.empty()) return std::nullopt;
  Builder b{rng, options, {}};
  b.s.world = std::move(world);
  for (int i = 0; i < static_cast<int>(b.s.world.bodies.size()); ++i) {
    const Body& body = b.s.world.bodies[static_cast<std::size_t>(i)];
    if (body.undetected) continue;
    Estimate e;
    e.body = i;
    e.clean = body.box;
    b.s.estimates.push_back(std::move(e));
  }
  if (b.s.estimates.empty()) return std::nullopt;
  b.add_false_estimates();
  if (!b.place_camera()) return std::nullopt;
  for (auto& e : b.s.estimates) {
    b.add_noise(e);
    b.add_keypoints(e);
  }
  b.assign_ids();
  b.s.numeric_ids = options.numeric_ids;
  return std::move(b.s);
}

std::string IndepScene::scene_json() const {
  const Eigen::Matrix3d cam_from_table = camera.rot.transpose();
  std::string out = "{\n";
  out += fmt::format("  \"camera\": {{\"fx\": {}, \"fy\": {}, \"cx\": {}, \"cy\": {}, \"width\": {}, \"height\": {}}},\n",
                     num(camera.fx, 3), num(camera.fy, 3), num(camera.cx, 3), num(camera.cy, 3), camera.width,
                     camera.height);
  out += fmt::format("  \"table\": {{\"pose\": {}}},\n", pose_json(cam_from_table, -(cam_from_table * camera.eye)));
  out += "  \"objects\": [";
  const bool numeric = numeric_ids;
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    const Estimate& e = estimates[i];
    out += i == 0 ? "\n" : ",\n";
    const std::string id = numeric ? e.id : "\"" + e.id + "\"";
    out += fmt::format("    {{\"id\": {}, \"model\": \"box\", \"size\": [{}, {}, {}], \"pose\": {}", id,
                       num(e.noisy.size.x(), 5), num(e.noisy.size.y(), 5), num(e.noisy.size.z(), 5),
                       pose_json(cam_from_table * e.noisy.rot, cam_from_table * (e.noisy.centre - camera.eye)));
    if (!e.kp_model.empty()) {
      std::string model, image;
      for (std::size_t k = 0; k < e.kp_model.size(); ++k) {
        const auto& m = e.kp_model[k];
        const auto& p = e.kp_image[k];
        model += fmt::format("{}[{}, {}, {}]", k ? ", " : "", num(m.x(), 6), num(m.y(), 6), num(m.z(), 6));
        image += fmt::format("{}[{}, {}]", k ? ", " : "", num(p.x(), 3), num(p.y(), 3));
      }
      out += fmt::format(",\n     \"keypoints\": {{\"model\": [{}],\n                   \"image\": [{}]}}", model, image);
    }
    out += "}";
  }
  out += "\n  ]\n}\n";
  return out;
}

std::string IndepScene::truth_json() const {
  const bool numeric = numeric_ids;
  auto id_of = [&](const std::string& id) { return numeric ? id : "\"" + id + "\""; };
  std::vector<std::string> good(world.bodies.size());  // id of a body's correct estimate
  for (const auto& e : estimates)
    if (e.body >= 0 && e.kind == FalseKind::none) good[static_cast<std::size_t>(e.body)] = e.id;
  auto body_id = [&](int i) { return i == kTable ? std::string("\"table\"") : id_of(good[static_cast<std::size_t>(i)]); };
  auto known = [&](int i) { return i == kTable || !good[static_cast<std::size_t>(i)].empty(); };
  std::string out = "{\n  \"objects\": [";
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    const Estimate& e = estimates[i];
    const bool real = e.kind == FalseKind::none;
    const bool hidden = real && world.hidden(e.body);
    const bool stable = real && world.bodies[static_cast<std::size_t>(e.body)].leans_on < 0;
    out += fmt::format("{}\n    {{\"id\": {}, \"false\": {}, \"hidden\": {}, \"stable\": {}, \"kind\": \"{}\"}}",
                       i ? "," : "", id_of(e.id), !real, hidden, stable, to_string(e.kind));
  }
  std::vector<std::pair<std::string, std::string>> support, contact;
  for (int i = 0; i < static_cast<int>(world.bodies.size()); ++i) {
    if (!known(i) || i == kTable) continue;
    for (int s : world.bodies[static_cast<std::size_t>(i)].rests_on)
      if (known(s)) support.emplace_back(body_id(i), body_id(s));
  }
  for (const auto& [a, c] : world.contact)
    if (known(a) && known(c)) contact.emplace_back(body_id(a), body_id(c));
  auto pairs = [](const std::vector<std::pair<std::string, std::string>>& list) {
    std::string t = "[";
    for (std::size_t i = 0; i < list.size(); ++i) t += fmt::format("{}[{}, {}]", i ? ", " : "", list[i].first, list[i].second);
    return t + "]";
  };
  out += "\n  ],\n  \"support\": " + pairs(support) + ",\n  \"contact\": " + pairs(contact) + "\n}\n";
  return out;
}

}  // namespace ksmc::tools::tabletop_indep
