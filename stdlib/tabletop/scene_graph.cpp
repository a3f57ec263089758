#include "stdlib/tabletop/result.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace ksmc::stdlib::tabletop {

std::optional<bool> decide(double p) {
  if (p > 0.6) return true;
  if (p < 0.4) return false;
  return std::nullopt;
}

namespace {

bool is_support(const Evidence& ev, std::size_t upper, std::size_t lower) {
  return ev.stable[upper] && ev.stable[lower] && ev.contact[upper][lower] && ev.higher[upper][lower];
}

}  // namespace

std::vector<Edge> support_edges(const Evidence& ev) {
  std::vector<Edge> out;
  for (std::size_t a = 0; a < ev.size(); ++a)
    for (std::size_t b = 0; b < ev.size(); ++b)
      if (a != b && is_support(ev, a, b)) out.emplace_back(ev.ids[a], ev.ids[b]);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Edge> unstable_contact_edges(const Evidence& ev) {
  std::vector<Edge> out;
  for (std::size_t a = 0; a < ev.size(); ++a)
    for (std::size_t b = a + 1; b < ev.size(); ++b) {
      if (!ev.contact[a][b] || is_support(ev, a, b) || is_support(ev, b, a)) continue;
      out.emplace_back(std::min(ev.ids[a], ev.ids[b]), std::max(ev.ids[a], ev.ids[b]));
    }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Edge> intersect_edges(const Evidence& ev) {
  std::vector<Edge> out;
  for (std::size_t a = 0; a < ev.size(); ++a)
    for (std::size_t b = a + 1; b < ev.size(); ++b)
      if (ev.intersect[a][b]) out.emplace_back(std::min(ev.ids[a], ev.ids[b]), std::max(ev.ids[a], ev.ids[b]));
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

// The edges of `all` whose ends are both not decided false.
std::vector<Edge> without_false(const TabletopResult& r, std::vector<Edge> all) {
  if (r.probabilities.empty()) return all;
  auto is_false = [&](const std::string& id) {
    const int i = r.scene.find(id);
    return i >= 0 && decide(r.probabilities.at(static_cast<std::size_t>(i)).false_prob).value_or(false);
  };
  std::erase_if(all, [&](const Edge& e) { return is_false(e.first) || is_false(e.second); });
  return all;
}

}  // namespace

std::vector<Edge> support_edges(const TabletopResult& r) { return without_false(r, support_edges(r.evidence)); }

std::vector<Edge> unstable_contact_edges(const TabletopResult& r) {
  return without_false(r, unstable_contact_edges(r.evidence));
}

void validate_result(const TabletopResult& r) {
  const std::size_t n = r.scene.objects.size();
  if (!r.probabilities.empty() && r.probabilities.size() != n)
    throw std::invalid_argument(
        fmt::format("tabletop result: {} probability entries for {} objects", r.probabilities.size(), n));
  if (r.evidence.size() != n + 1)
    throw std::invalid_argument(fmt::format("tabletop result: evidence has {} bodies, scene has {} objects + table",
                                            r.evidence.size(), n));
  for (std::size_t i = 0; i < n; ++i) {
    if (r.evidence.ids[Evidence::body(i)] != r.scene.objects[i].id)
      throw std::invalid_argument(fmt::format("tabletop result: evidence body {} is \"{}\", scene object is \"{}\"",
                                              i + 1, r.evidence.ids[Evidence::body(i)], r.scene.objects[i].id));
    if (r.probabilities.empty()) continue;
    for (double p : {r.probabilities[i].false_prob, r.probabilities[i].hidden_prob})
      if (!(p >= 0.0 && p <= 1.0))
        throw std::invalid_argument(
            fmt::format("tabletop result: object \"{}\": probability {} outside [0, 1]", r.scene.objects[i].id, p));
  }
}

nlohmann::json id_json(const Scene& scene, const std::string& id) {
  const int i = scene.find(id);
  if (i >= 0 && scene.objects[static_cast<std::size_t>(i)].numeric_id) return nlohmann::json::parse(id);
  return id;
}

nlohmann::json scene_graph_json(const TabletopResult& r) {
  validate_result(r);
  using nlohmann::json;
  auto decision = [](double p) { const auto d = decide(p); return d ? json(*d) : json(nullptr); };
  json objects = json::array();
  for (std::size_t i = 0; i < r.scene.objects.size(); ++i) {
    const SceneObject& o = r.scene.objects[i];
    const Pose cam = r.scene.camera_pose(o);
    json pose = {{"t", {cam.t.x(), cam.t.y(), cam.t.z()}}, {"q", {cam.q.w(), cam.q.x(), cam.q.y(), cam.q.z()}}};
    json entry = {{"id", id_json(r.scene, o.id)},
                  {"pose", pose},
                  {"stable", static_cast<bool>(r.evidence.stable[Evidence::body(i)])}};
    if (!r.probabilities.empty()) {
      const auto& p = r.probabilities[i];
      entry["false_prob"] = p.false_prob;
      entry["hidden_prob"] = p.hidden_prob;
      entry["false"] = decision(p.false_prob);
      entry["hidden"] = decision(p.hidden_prob);
    }
    objects.push_back(std::move(entry));
  }
  json support = json::array();
  for (const auto& [u, l] : support_edges(r)) support.push_back({id_json(r.scene, u), id_json(r.scene, l)});
  json contact = json::array();
  for (const auto& [a, b] : unstable_contact_edges(r))
    contact.push_back({id_json(r.scene, a), id_json(r.scene, b)});
  json intersect = json::array();
  for (const auto& [a, b] : intersect_edges(r.evidence)) intersect.push_back({id_json(r.scene, a), id_json(r.scene, b)});
  return json{{"objects", objects}, {"support", support}, {"contact", contact}, {"intersect", intersect}};
}

}  // namespace ksmc::stdlib::tabletop
