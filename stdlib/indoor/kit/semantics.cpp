#include "stdlib/indoor/kit/semantics.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "runtime/mln/evidence.h"
#include "runtime/mln/inference.h"

namespace ksmc::stdlib::indoor::kit {

namespace dom = runtime::domain;
namespace mln = runtime::mln;

GeomClass classify_unit(const OrientedRect& r, double resolution, const ClassifierSettings& c) {
  const double lo = std::min(std::abs(r.w), std::abs(r.h)) * resolution;
  const double hi = std::max(std::abs(r.w), std::abs(r.h)) * resolution;
  if (hi > c.big_size_m) return GeomClass::HallLike;
  if (lo <= 0.0 || hi / lo > c.big_ratio) return GeomClass::CorridorLike;
  return GeomClass::RoomLike;
}

std::optional<WallPair> connecting_walls(const OrientedRect& a, const OrientedRect& b, double dilate_cells) {
  const auto ca = a.corners();
  const auto cb = b.corners();
  const double max_gap = 2.0 * dilate_cells + 1.0;
  const double sin_tol = std::sin(10.0 * 3.14159265358979323846 / 180.0);
  std::optional<WallPair> best;
  for (int i = 0; i < 4; ++i) {
    const Point2 p0 = ca[static_cast<std::size_t>(i)], p1 = ca[static_cast<std::size_t>((i + 1) % 4)];
    const double la = std::hypot(p1.x - p0.x, p1.y - p0.y);
    if (!(la > 0.0)) continue;
    const double dx = (p1.x - p0.x) / la, dy = (p1.y - p0.y) / la;
    for (int j = 0; j < 4; ++j) {
      const Point2 q0 = cb[static_cast<std::size_t>(j)], q1 = cb[static_cast<std::size_t>((j + 1) % 4)];
      const double lb = std::hypot(q1.x - q0.x, q1.y - q0.y);
      if (!(lb > 0.0)) continue;
      const double ex = (q1.x - q0.x) / lb, ey = (q1.y - q0.y) / lb;
      if (std::abs(dx * ey - dy * ex) > sin_tol) continue;
      const double mx = 0.5 * (q0.x + q1.x) - p0.x, my = 0.5 * (q0.y + q1.y) - p0.y;
      if (std::abs(dx * my - dy * mx) > max_gap) continue;
      const double t0 = dx * (q0.x - p0.x) + dy * (q0.y - p0.y);
      const double t1 = dx * (q1.x - p0.x) + dy * (q1.y - p0.y);
      const double ov = std::min(la, std::max(t0, t1)) - std::max(0.0, std::min(t0, t1));
      if (!(ov > dilate_cells)) continue;
      if (!best || ov > best->overlap) best = WallPair{i, j, ov, la, lb};
    }
  }
  return best;
}

std::optional<double> wall_length_diff(const OrientedRect& a, const OrientedRect& b, double dilate_cells,
                                       double resolution) {
  const auto w = connecting_walls(a, b, dilate_cells);
  if (!w) return std::nullopt;
  return std::abs(w->length_a - w->length_b) * resolution;
}

namespace {

std::int32_t need_predicate(const mln::Program& p, const std::string& name, bool query, std::size_t arity) {
  const auto id = p.find_predicate(name);
  if (!id) throw dom::ConfigError("indoor kit: the Markov logic program has no predicate " + name);
  const mln::Predicate& pr = p.predicates[static_cast<std::size_t>(*id)];
  if (pr.query != query || pr.arg_types.size() != arity)
    throw dom::ConfigError("indoor kit: predicate " + name + " must be " + (query ? "a query" : "evidence") +
                           " predicate of arity " + std::to_string(arity));
  return *id;
}

}  // namespace

SemanticEngine::SemanticEngine(const SemanticSettings& settings, const dom::MlnBinding& binding, double resolution,
                               std::uint64_t seed, std::size_t cache_size)
    : settings_(settings), binding_(binding), resolution_(resolution), seed_(seed), cache_(cache_size) {
  if (!binding.program || !binding.make_domain || !binding.ground)
    throw dom::ConfigError("indoor kit: the semantic extractors need the generated Markov logic binding");
  const mln::Program& p = binding.program();
  const auto t = p.find_type("unit");
  if (!t) throw dom::ConfigError("indoor kit: the Markov logic program has no type 'unit'");
  unit_type_ = *t;
  p_roli_ = need_predicate(p, "RoLi", false, 1);
  p_coli_ = need_predicate(p, "CoLi", false, 1);
  p_hali_ = need_predicate(p, "HaLi", false, 1);
  p_muldoor_ = need_predicate(p, "MulDoor", false, 1);
  p_adj_ = need_predicate(p, "Adj", false, 2);
  p_sale_ = need_predicate(p, settings.sale_predicate, true, 2);
  for (int k = 0; k < kTypes; ++k)
    p_type_[static_cast<std::size_t>(k)] = need_predicate(p, settings.type_predicates[static_cast<std::size_t>(k)], true, 1);
}

SemanticResult SemanticEngine::evaluate(const World& world) {
  ++stats_.calls;
  const auto units = world.units();
  const int n = static_cast<int>(units.size());
  // Key: n, per unit (class, muldoor), then the adjacency pairs (i, j), i < j.
  std::vector<std::int32_t> key;
  key.reserve(static_cast<std::size_t>(1 + 2 * n));
  key.push_back(n);
  for (const Unit& u : units) {
    key.push_back(static_cast<std::int32_t>(classify_unit(u.rect, resolution_, settings_.classifier)));
    key.push_back(world.door_count(u.id) >= settings_.multi_door_min ? 1 : 0);
  }
  std::vector<std::pair<int, int>> adj;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (connecting_walls(units[static_cast<std::size_t>(i)].rect, units[static_cast<std::size_t>(j)].rect,
                           settings_.adjacent_dilate_cells)) {
        adj.emplace_back(i, j);
        key.push_back(i);
        key.push_back(j);
      }
  std::shared_ptr<const Indexed> r = cache_.find(key);
  if (r) {
    ++stats_.cache_hits;
  } else {
    r = infer(key, n, adj);
    cache_.insert(key, r);
  }
  SemanticResult out;
  out.method = r->method;
  for (int i = 0; i < n; ++i) {
    UnitSemantics s;
    s.id = units[static_cast<std::size_t>(i)].id;
    s.type_probs = r->probs[static_cast<std::size_t>(i)];
    for (int k = 1; k < kTypes; ++k)
      if (s.type_probs[static_cast<std::size_t>(k)] > s.type_probs[static_cast<std::size_t>(s.type)]) s.type = k;
    out.units.push_back(s);
  }
  for (auto [i, j] : adj) out.adjacent.emplace_back(units[static_cast<std::size_t>(i)].id, units[static_cast<std::size_t>(j)].id);
  for (auto [i, j] : r->same_length)
    out.same_length.emplace_back(units[static_cast<std::size_t>(i)].id, units[static_cast<std::size_t>(j)].id);
  return out;
}

std::shared_ptr<const SemanticEngine::Indexed> SemanticEngine::infer(const std::vector<std::int32_t>& key, int n,
                                                                     const std::vector<std::pair<int, int>>& adj) {
  const auto t0 = std::chrono::steady_clock::now();
  auto res = std::make_shared<Indexed>();
  res->probs.assign(static_cast<std::size_t>(n), {});
  if (n == 0) {
    res->method = "none";
    return res;
  }
  const mln::Program& program = binding_.program();
  mln::Domain domain = binding_.make_domain();
  for (int i = 0; i < n; ++i) domain.add(unit_type_, "U" + std::to_string(i));
  mln::Evidence ev(program, domain);
  for (int i = 0; i < n; ++i) {
    const std::int32_t a[1] = {i};
    const auto cls = static_cast<GeomClass>(key[static_cast<std::size_t>(1 + 2 * i)]);
    ev.set(p_roli_, a, cls == GeomClass::RoomLike);
    ev.set(p_coli_, a, cls == GeomClass::CorridorLike);
    ev.set(p_hali_, a, cls == GeomClass::HallLike);
    ev.set(p_muldoor_, a, key[static_cast<std::size_t>(2 + 2 * i)] != 0);
    for (int j = 0; j < n; ++j) {
      const std::int32_t ab[2] = {i, j};
      ev.set(p_adj_, ab, false);
    }
  }
  for (auto [i, j] : adj) {
    const std::int32_t ab[2] = {i, j}, ba[2] = {j, i};
    ev.set(p_adj_, ab, true);
    ev.set(p_adj_, ba, true);
  }
  const mln::Grounding g = binding_.ground(domain, ev);
  mln::InferenceOptions opt;
  opt.method = mln::Method::Auto;
  opt.compute_log_z = false;
  opt.mcsat.seed = seed_;
  opt.mcsat.samples = 500;
  opt.mcsat.burn_in = 50;
  const mln::InferenceResult r = mln::infer(g.network, opt);
  res->method = r.method;
  for (int i = 0; i < n; ++i) {
    const std::int32_t a[1] = {i};
    for (int k = 0; k < kTypes; ++k)
      res->probs[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] = g.marginal(r, p_type_[static_cast<std::size_t>(k)], a);
  }
  for (auto [i, j] : adj) {
    const std::int32_t ab[2] = {i, j};
    const double p = g.marginal(r, p_sale_, ab);
    const bool pass = settings_.sale_op == ">=" ? p >= settings_.sale_threshold : p > settings_.sale_threshold;
    if (pass) res->same_length.emplace_back(i, j);
  }
  ++stats_.inferences;
  stats_.inference_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace ksmc::stdlib::indoor::kit
