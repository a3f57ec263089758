#include "stdlib/tabletop/perception/truth_eval.h"

#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "stdlib/tabletop/perception/cloud_io.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

std::vector<double> numbers(const nlohmann::json& o, const std::string& where, const char* key, std::size_t n,
                            const std::string& file) {
  if (!o.contains(key)) throw CloudError(fmt::format("{}: {}.{}: missing field", file, where, key));
  const auto& a = o[key];
  if (!a.is_array() || a.size() != n)
    throw CloudError(fmt::format("{}: {}.{}: expected an array of {} numbers", file, where, key, n));
  std::vector<double> v;
  for (const auto& x : a) {
    if (!x.is_number()) throw CloudError(fmt::format("{}: {}.{}: expected a number", file, where, key));
    v.push_back(x.get<double>());
  }
  return v;
}

TruthReport finish(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth, Registration reg) {
  TruthReport rep;
  rep.objects.assign(truth.size(), {});
  const Eigen::Matrix3d r = reg.source_to_target.linear();
  for (std::size_t e = 0; e < estimates.size(); ++e) {
    const int t = reg.match[e];
    if (t < 0) {
      ++rep.spurious;
      continue;
    }
    const TruthBox& g = truth[static_cast<std::size_t>(t)];
    const TruthBox& s = estimates[e];
    ObjectError& oe = rep.objects[static_cast<std::size_t>(t)];
    oe.estimate = static_cast<int>(e);
    oe.error = compare_boxes(reg.source_to_target * s.centre, r * s.axes, s.size, g.centre, g.axes, g.size);
  }
  for (const auto& o : rep.objects) rep.missed += o.estimate < 0 ? 1 : 0;
  rep.registration = std::move(reg);
  return rep;
}

std::vector<Eigen::Vector3d> centres(const std::vector<TruthBox>& boxes) {
  std::vector<Eigen::Vector3d> c;
  for (const auto& b : boxes) c.push_back(b.centre);
  return c;
}

}  // namespace

std::vector<TruthBox> read_obb_world(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path);
  if (!in) throw CloudError(fmt::format("{}: cannot open file", file));
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw CloudError(fmt::format("{}: invalid JSON: {}", file, e.what()));
  }
  if (!doc.is_object() || !doc.contains("objects") || !doc["objects"].is_array())
    throw CloudError(fmt::format("{}: objects: missing array", file));
  std::vector<TruthBox> out;
  for (std::size_t i = 0; i < doc["objects"].size(); ++i) {
    const auto& o = doc["objects"][i];
    const std::string where = fmt::format("objects[{}]", i);
    if (!o.is_object()) throw CloudError(fmt::format("{}: {}: expected an object", file, where));
    TruthBox b;
    b.name = o.contains("class") && o["class"].is_string() ? o["class"].get<std::string>() : where;
    const auto c = numbers(o, where, "center_m", 3, file);
    const auto r = numbers(o, where, "R_rowmajor", 9, file);
    const auto s = numbers(o, where, "size_m", 3, file);
    b.centre = Eigen::Vector3d(c[0], c[1], c[2]);
    for (int k = 0; k < 9; ++k) b.axes(k / 3, k % 3) = r[static_cast<std::size_t>(k)];
    b.size = Eigen::Vector3d(s[0], s[1], s[2]);
    out.push_back(std::move(b));
  }
  return out;
}

std::vector<TruthBox> camera_frame_boxes(const Scene& scene) {
  std::vector<TruthBox> out;
  for (const auto& o : scene.objects) {
    const Pose p = scene.camera_pose(o);
    out.push_back({o.id, p.t, p.rotation(), o.size});
  }
  return out;
}

TruthReport evaluate_registered(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth, double gate) {
  return finish(estimates, truth, register_unmatched(centres(estimates), centres(truth), gate));
}

TruthReport evaluate_matched(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth,
                             Registration registration) {
  return finish(estimates, truth, std::move(registration));
}

TruthReport evaluate_with_transform(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth,
                                    const Eigen::Isometry3d& transform, double gate) {
  return finish(estimates, truth, match_nearest(centres(estimates), centres(truth), transform, gate));
}

TruthReport evaluate_same_frame(const std::vector<TruthBox>& estimates, const std::vector<TruthBox>& truth, double gate) {
  return evaluate_with_transform(estimates, truth, Eigen::Isometry3d::Identity(), gate);
}

}  // namespace ksmc::stdlib::tabletop::perception
