#include "stdlib/tabletop/scene_io.h"

#include "stdlib/tabletop/json_reader.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runtime/io/json_error.h"

namespace ksmc::stdlib::tabletop {

namespace {

using nlohmann::json;
using detail::Reader;

Camera read_camera(const Reader& r, const json& j, const std::string& path) {
  Camera c;
  c.fx = r.positive(r.member(j, path, "fx"), Reader::join(path, "fx"));
  c.fy = r.positive(r.member(j, path, "fy"), Reader::join(path, "fy"));
  c.cx = r.number(r.member(j, path, "cx"), Reader::join(path, "cx"));
  c.cy = r.number(r.member(j, path, "cy"), Reader::join(path, "cy"));
  c.width = r.positive_int(r.member(j, path, "width"), Reader::join(path, "width"));
  c.height = r.positive_int(r.member(j, path, "height"), Reader::join(path, "height"));
  const std::pair<const char*, double> checks[] = {{"fx", c.fx}, {"fy", c.fy}, {"cx", c.cx}, {"cy", c.cy}};
  for (const auto& [key, v] : checks)
    if (std::abs(v) > 1e7) r.fail(Reader::join(path, key), fmt::format("value {} out of range (|v| > 1e7)", v));
  return c;
}

SceneObject read_object(const Reader& r, const json& j, const std::string& path, const Pose& camera_to_table,
                        const SceneOptions& options) {
  SceneObject o;
  const json& id = r.member(j, path, "id");
  if (id.is_number()) {  // numeric ids are accepted and echoed back as numbers (scene_graph_json)
    o.id = id.dump();
    o.numeric_id = true;
  } else if (id.is_string()) {
    o.id = id.get<std::string>();
  } else {
    r.fail(Reader::join(path, "id"), fmt::format("expected a string or a number, got {}", id.type_name()));
  }
  if (o.id.empty()) r.fail(Reader::join(path, "id"), "empty id");
  if (o.id == kTableId) r.fail(Reader::join(path, "id"), "id \"table\" is reserved for the table");
  o.model = r.string(r.member(j, path, "model"), Reader::join(path, "model"));
  const std::string spath = Reader::join(path, "size");
  o.size = r.bounded<3>(r.member(j, path, "size"), spath);
  for (int i = 0; i < 3; ++i)
    if (!(o.size[i] > 0.0))
      r.fail(Reader::index(spath, static_cast<std::size_t>(i)), fmt::format("size must be > 0, got {}", o.size[i]));
  const Pose in_camera = r.pose(r.member(j, path, "pose"), Reader::join(path, "pose"), options.quaternion_tolerance);
  o.pose = camera_to_table.compose(in_camera);

  if (const json* kp = r.optional_member(j, path, "keypoints")) {
    const std::string kpath = Reader::join(path, "keypoints");
    const std::string mpath = Reader::join(kpath, "model");
    const std::string ipath = Reader::join(kpath, "image");
    const json& model = r.array(r.member(*kp, kpath, "model"), mpath);
    const json& image = r.array(r.member(*kp, kpath, "image"), ipath);
    if (model.size() != image.size())
      r.fail(kpath, fmt::format("keypoint lists differ in length: model has {}, image has {}", model.size(),
                                image.size()));
    for (std::size_t i = 0; i < model.size(); ++i) {
      o.keypoints_model.push_back(r.bounded<3>(model[i], Reader::index(mpath, i)));
      o.keypoints_image.push_back(r.bounded<2>(image[i], Reader::index(ipath, i), 1e7));
    }
  }
  return o;
}

}  // namespace

SceneLoad parse_scene(const nlohmann::json& doc, const std::string& source_name,
                      const std::filesystem::path& base_dir, const SceneOptions& options) {
  SceneLoad out;
  Reader r(source_name, out.warnings);
  if (!doc.is_object()) r.fail("(root)", "expected a JSON object");
  Scene& s = out.scene;
  s.camera = read_camera(r, r.member(doc, "", "camera"), "camera");

  const json& table = r.member(doc, "", "table");
  s.table_in_camera = r.pose(r.member(table, "table", "pose"), "table.pose", options.quaternion_tolerance);
  s.table.size = options.table_size;
  if (const json* ts = r.optional_member(table, "table", "size")) {
    s.table.size = r.bounded<3>(*ts, "table.size");
    for (int i = 0; i < 3; ++i)
      if (!(s.table.size[i] > 0.0))
        r.fail(Reader::index("table.size", static_cast<std::size_t>(i)), "size must be > 0");
  }

  if (const json* noise = r.optional_member(doc, "", "depth_noise")) {
    s.depth_noise = r.positive(*noise, "depth_noise");
    if (s.depth_noise > 1.0) r.fail("depth_noise", fmt::format("{} m is not a depth noise (> 1 m)", s.depth_noise));
  }

  if (const json* img = r.optional_member(doc, "", "image")) {
    const std::string rel = r.string(*img, "image");
    if (!rel.empty()) s.image = std::filesystem::path(rel).is_absolute() ? std::filesystem::path(rel) : base_dir / rel;
  }

  const Pose camera_to_table = s.table_in_camera.inverse();
  const json& objects = r.array(r.member(doc, "", "objects"), "objects");
  if (objects.empty()) r.fail("objects", "empty scene: no objects");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string path = Reader::index("objects", i);
    SceneObject o = read_object(r, objects[i], path, camera_to_table, options);
    if (!ids.insert(o.id).second) r.fail(Reader::join(path, "id"), fmt::format("duplicate id \"{}\"", o.id));
    s.objects.push_back(std::move(o));
  }
  return out;
}

SceneLoad load_scene(const std::filesystem::path& path, const SceneOptions& options) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(fmt::format("{}: cannot open file", name));
  std::stringstream buf;
  buf << in.rdbuf();
  nlohmann::json doc;
  const std::string text = buf.str();
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for 1e999
    throw SceneError(ksmc::runtime::io::json_error_message(name, text, e));
  }
  return parse_scene(doc, name, path.parent_path(), options);
}

}  // namespace ksmc::stdlib::tabletop
