#include "tools/tabletop_sim/scene_writer.h"

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"

namespace ksmc::tools::tabletop_sim {

namespace {

std::string num(double v, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (s.find_first_not_of("-0.") == std::string::npos && s.front() == '-') s.erase(0, 1);  // no "-0.000"
  return s;
}

std::string vec(const Eigen::Vector3d& v, int decimals) {
  return fmt::format("[{}, {}, {}]", num(v.x(), decimals), num(v.y(), decimals), num(v.z(), decimals));
}

std::string pose_json(const Pose& p) {
  const Eigen::Quaterniond q = canonical(p.q);
  return fmt::format(R"({{"t": {}, "q": [{}, {}, {}, {}]}})", vec(p.t, 6), num(q.w(), 9), num(q.x(), 9),
                     num(q.y(), 9), num(q.z(), 9));
}

// A list of points, five per line, indented under its key.
template <typename Points, typename Format>
std::string point_list(const Points& pts, Format format, const std::string& indent) {
  std::string out = "[";
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i > 0) out += (i % 5 == 0) ? ",\n" + indent + " " : ", ";
    out += format(pts[i]);
  }
  return out + "]";
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// An object id as JSON: a number when the scene uses numeric ids (the table stays "table").
std::string id_json(const GeneratedScene& scene, const std::string& id) {
  return scene.numeric_ids && id != "table" ? id : quoted(id);
}

}  // namespace

std::string scene_json(const GeneratedScene& scene) {
  const Camera& c = scene.camera;
  const Pose camera_from_table = scene.table_from_camera.inverse();
  std::string out = "{\n";
  out += fmt::format(
      "  \"camera\": {{\"fx\": {}, \"fy\": {}, \"cx\": {}, \"cy\": {}, \"width\": {}, \"height\": {}}},\n",
      num(c.fx, 3), num(c.fy, 3), num(c.cx, 3), num(c.cy, 3), c.width, c.height);
  out += fmt::format("  \"table\": {{\"pose\": {}}},\n", pose_json(camera_from_table));
  out += "  \"objects\": [";
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    out += i == 0 ? "\n" : ",\n";
    out += fmt::format("    {{\"id\": {}, \"model\": {}, \"size\": {},\n", id_json(scene, o.id),
                       quoted(std::string(o.item.model)), vec(o.item.size, 5));
    out += fmt::format("     \"pose\": {},\n", pose_json(camera_from_table * o.estimate));
    const std::string indent(18, ' ');
    out += fmt::format("     \"keypoints\": {{\n       \"model\": {},\n       \"image\": {}}}}}",
                       point_list(o.keypoints.model, [](const Eigen::Vector3d& p) { return vec(p, 6); }, indent),
                       point_list(o.keypoints.image,
                                  [](const Eigen::Vector2d& p) { return fmt::format("[{}, {}]", num(p.x(), 3), num(p.y(), 3)); },
                                  indent));
  }
  out += "\n  ]\n}\n";
  return out;
}

std::string truth_json(const GeneratedScene& scene) {
  std::string out = "{\n  \"objects\": [";
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    out += i == 0 ? "\n" : ",\n";
    out += fmt::format("    {{\"id\": {}, \"false\": {}, \"hidden\": {}, \"stable\": {}}}", id_json(scene, o.id),
                       o.false_kind != FalseKind::none, o.hidden, o.stable);
  }
  out += "\n  ],\n";
  auto pairs = [&](const std::vector<std::pair<std::string, std::string>>& list) {
    std::string s = "[";
    for (std::size_t i = 0; i < list.size(); ++i) {
      if (i > 0) s += ", ";
      s += fmt::format("[{}, {}]", id_json(scene, list[i].first), id_json(scene, list[i].second));
    }
    return s + "]";
  };
  out += "  \"support\": " + pairs(scene.support) + ",\n";
  out += "  \"contact\": " + pairs(scene.contact) + "\n}\n";
  return out;
}

void write_scene_files(const std::filesystem::path& dir, const std::string& stem, const GeneratedScene& scene) {
  runtime::io::write_file_atomic(dir / (stem + ".json"), scene_json(scene));
  runtime::io::write_file_atomic(dir / (stem + ".truth.json"), truth_json(scene));
}

}  // namespace ksmc::tools::tabletop_sim
