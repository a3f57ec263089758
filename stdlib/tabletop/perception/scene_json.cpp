#include "stdlib/tabletop/perception/scene_json.h"

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"

namespace ksmc::stdlib::tabletop::perception {

namespace {

std::string vec3(const Eigen::Vector3d& v) { return fmt::format("[{:.6f}, {:.6f}, {:.6f}]", v.x(), v.y(), v.z()); }

std::string pose_text(const Pose& p) {
  Eigen::Quaterniond q = p.q.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return fmt::format(R"({{"t": {}, "q": [{:.9f}, {:.9f}, {:.9f}, {:.9f}]}})", vec3(p.t), q.w(), q.x(), q.y(), q.z());
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string scene_json_text(const Scene& s) {
  const Camera& c = s.camera;
  std::string out = "{\n";
  out += fmt::format(
      R"(  "camera": {{"fx": {:.3f}, "fy": {:.3f}, "cx": {:.3f}, "cy": {:.3f}, "width": {}, "height": {}}},)", c.fx,
      c.fy, c.cx, c.cy, c.width, c.height);
  out += "\n";
  out += fmt::format(R"(  "table": {{"pose": {}, "size": {}}},)", pose_text(s.table_in_camera), vec3(s.table.size));
  out += "\n";
  if (!s.image.empty()) out += fmt::format("  \"image\": {},\n", json_string(s.image.string()));
  if (s.depth_noise > 0.0) out += fmt::format("  \"depth_noise\": {:.6f},\n", s.depth_noise);
  out += "  \"objects\": [";
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const SceneObject& o = s.objects[i];
    out += i ? ",\n" : "\n";
    out += fmt::format(R"(    {{"id": {}, "model": {}, "size": {}, "pose": {})", json_string(o.id), json_string(o.model),
                       vec3(o.size), pose_text(s.camera_pose(o)));
    if (!o.keypoints_model.empty()) {
      std::string model, image;
      for (std::size_t k = 0; k < o.keypoints_model.size(); ++k) {
        model += (k ? ", " : "") + vec3(o.keypoints_model[k]);
        image += fmt::format("{}[{:.3f}, {:.3f}]", k ? ", " : "", o.keypoints_image[k].x(), o.keypoints_image[k].y());
      }
      out += fmt::format(R"(, "keypoints": {{"model": [{}], "image": [{}]}})", model, image);
    }
    out += "}";
  }
  out += "\n  ]\n}\n";
  return out;
}

void write_scene_json(const std::filesystem::path& path, const Scene& scene) {
  runtime::io::write_file_atomic(path, scene_json_text(scene));
}

}  // namespace ksmc::stdlib::tabletop::perception
