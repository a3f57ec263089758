#include "stdlib/tabletop/scene_io.h"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace ksmc::stdlib::tabletop {

namespace {

using nlohmann::json;

class Reader {
 public:
  Reader(std::string source, std::vector<std::string>& warnings)
      : source_(std::move(source)), warnings_(warnings) {}

  [[noreturn]] void fail(const std::string& path, const std::string& msg) const {
    throw SceneError(fmt::format("{}: {}: {}", source_, path, msg));
  }
  void warn(const std::string& path, const std::string& msg) const {
    warnings_.push_back(fmt::format("{}: {}: {}", source_, path, msg));
  }

  const json& member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    if (it == obj.end()) fail(join(path, key), "missing field");
    return *it;
  }
  const json* optional_member(const json& obj, const std::string& path, const char* key) const {
    if (!obj.is_object()) fail(path, "expected an object");
    auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  double number(const json& j, const std::string& path) const {
    if (!j.is_number()) fail(path, fmt::format("expected a number, got {}", j.type_name()));
    const double v = j.get<double>();
    if (!std::isfinite(v)) fail(path, "not a finite number");
    return v;
  }
  double positive(const json& j, const std::string& path) const {
    const double v = number(j, path);
    if (!(v > 0.0)) fail(path, fmt::format("must be > 0, got {}", v));
    return v;
  }
  int positive_int(const json& j, const std::string& path) const {
    if (!j.is_number_integer()) fail(path, fmt::format("expected an integer, got {}", j.type_name()));
    const auto v = j.get<long long>();
    if (v <= 0 || v > 1000000) fail(path, fmt::format("must be a positive image dimension, got {}", v));
    return static_cast<int>(v);
  }
  std::string string(const json& j, const std::string& path) const {
    if (!j.is_string()) fail(path, fmt::format("expected a string, got {}", j.type_name()));
    return j.get<std::string>();
  }
  const json& array(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(path, fmt::format("expected an array, got {}", j.type_name()));
    return j;
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vec(const json& j, const std::string& path) const {
    array(j, path);
    if (j.size() != static_cast<std::size_t>(N))
      fail(path, fmt::format("expected {} numbers, got {}", N, j.size()));
    Eigen::Matrix<double, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = number(j[static_cast<std::size_t>(i)], index(path, static_cast<std::size_t>(i)));
    return v;
  }

  Pose pose(const json& j, const std::string& path, double tol) const {
    Pose p;
    p.t = vec<3>(member(j, path, "t"), join(path, "t"));
    const std::string qpath = join(path, "q");
    const Eigen::Vector4d q = vec<4>(member(j, path, "q"), qpath);  // w, x, y, z
    const double n = q.norm();
    if (n < 1e-12) fail(qpath, "zero quaternion");
    if (std::abs(n - 1.0) > tol) warn(qpath, fmt::format("non-unit quaternion (norm {:.6g}), normalised", n));
    p.q = Eigen::Quaterniond(q[0] / n, q[1] / n, q[2] / n, q[3] / n);
    return p;
  }

  static std::string join(const std::string& path, const char* key) {
    return path.empty() ? std::string(key) : path + "." + key;
  }
  static std::string index(const std::string& path, std::size_t i) { return fmt::format("{}[{}]", path, i); }

 private:
  std::string source_;
  std::vector<std::string>& warnings_;
};

Camera read_camera(const Reader& r, const json& j, const std::string& path) {
  Camera c;
  c.fx = r.positive(r.member(j, path, "fx"), Reader::join(path, "fx"));
  c.fy = r.positive(r.member(j, path, "fy"), Reader::join(path, "fy"));
  c.cx = r.number(r.member(j, path, "cx"), Reader::join(path, "cx"));
  c.cy = r.number(r.member(j, path, "cy"), Reader::join(path, "cy"));
  c.width = r.positive_int(r.member(j, path, "width"), Reader::join(path, "width"));
  c.height = r.positive_int(r.member(j, path, "height"), Reader::join(path, "height"));
  return c;
}

SceneObject read_object(const Reader& r, const json& j, const std::string& path, const Pose& camera_to_table,
                        const SceneOptions& options) {
  SceneObject o;
  o.id = r.string(r.member(j, path, "id"), Reader::join(path, "id"));
  if (o.id.empty()) r.fail(Reader::join(path, "id"), "empty id");
  if (o.id == kTableId) r.fail(Reader::join(path, "id"), "id \"table\" is reserved for the table");
  o.model = r.string(r.member(j, path, "model"), Reader::join(path, "model"));
  const std::string spath = Reader::join(path, "size");
  o.size = r.vec<3>(r.member(j, path, "size"), spath);
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
      o.keypoints_model.push_back(r.vec<3>(model[i], Reader::index(mpath, i)));
      o.keypoints_image.push_back(r.vec<2>(image[i], Reader::index(ipath, i)));
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
    s.table.size = r.vec<3>(*ts, "table.size");
    for (int i = 0; i < 3; ++i)
      if (!(s.table.size[i] > 0.0))
        r.fail(Reader::index("table.size", static_cast<std::size_t>(i)), "size must be > 0");
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
  try {
    doc = nlohmann::json::parse(buf.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw SceneError(fmt::format("{}: invalid JSON: {}", name, e.what()));
  }
  return parse_scene(doc, name, path.parent_path(), options);
}

}  // namespace ksmc::stdlib::tabletop
