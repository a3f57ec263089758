#include "stdlib/tabletop/hope_import.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "runtime/io/json_error.h"
#include "stdlib/tabletop/json_reader.h"

namespace ksmc::stdlib::tabletop {

namespace {

using detail::Reader;
using nlohmann::json;

Eigen::Matrix4d matrix4(const Reader& r, const json& j, const std::string& path) {
  r.array(j, path);
  if (j.size() != 4) r.fail(path, fmt::format("expected 4 rows, got {}", j.size()));
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i) m.row(i) = r.vec<4>(j[static_cast<std::size_t>(i)], Reader::index(path, static_cast<std::size_t>(i))).transpose();
  return m;
}

Eigen::Matrix3d matrix3(const Reader& r, const json& j, const std::string& path) {
  r.array(j, path);
  if (j.size() != 3) r.fail(path, fmt::format("expected 3 rows, got {}", j.size()));
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i) m.row(i) = r.vec<3>(j[static_cast<std::size_t>(i)], Reader::index(path, static_cast<std::size_t>(i))).transpose();
  return m;
}

// Rigid transform from a 4×4 matrix whose translation is scaled by `to_metres`.
Eigen::Isometry3d rigid(const Reader& r, const Eigen::Matrix4d& m, const std::string& path, double to_metres) {
  const Eigen::Matrix3d rot = m.topLeftCorner<3, 3>();
  if ((rot.transpose() * rot - Eigen::Matrix3d::Identity()).norm() > 1e-3 || rot.determinant() < 0.0)
    r.fail(path, "rotation part is not a proper rotation");
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-9) r.fail(path, "last row must be [0, 0, 0, 1]");
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  Eigen::Quaterniond q(rot);
  q.normalize();
  iso.linear() = q.toRotationMatrix();
  iso.translation() = to_metres * m.topRightCorner<3, 1>();
  return iso;
}

}  // namespace

HopeImport import_hope(const json& meta, const std::string& source_name, const HopeImportOptions& options) {
  HopeImport out;
  Reader r(source_name, out.warnings);
  const json& cam = r.member(meta, "", "camera");
  const Eigen::Matrix3d k = matrix3(r, r.member(cam, "camera", "intrinsics"), "camera.intrinsics");
  Scene& s = out.scene;
  s.camera.fx = k(0, 0);
  s.camera.fy = k(1, 1);
  s.camera.cx = k(0, 2);
  s.camera.cy = k(1, 2);
  if (!(s.camera.fx > 0.0 && s.camera.fy > 0.0)) r.fail("camera.intrinsics", "focal lengths must be > 0");
  s.camera.width = r.positive_int(r.member(cam, "camera", "width"), "camera.width");
  s.camera.height = r.positive_int(r.member(cam, "camera", "height"), "camera.height");
  const Eigen::Isometry3d world_from_cam =
      rigid(r, matrix4(r, r.member(cam, "camera", "extrinsics"), "camera.extrinsics"), "camera.extrinsics", 1.0);

  const json& objects = r.array(r.member(meta, "", "objects"), "objects");
  if (objects.empty()) r.fail("objects", "empty scene: no objects");
  struct Raw {
    std::string id, model;
    Eigen::Vector3d size;
    Eigen::Isometry3d world_from_obb;
  };
  std::vector<Raw> raw;
  std::map<std::string, int> class_count;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const std::string path = Reader::index("objects", i);
    Raw o;
    o.model = r.string(r.member(objects[i], path, "class"), Reader::join(path, "class"));
    const int n = class_count[o.model]++;
    o.id = n == 0 ? o.model : fmt::format("{}_{}", o.model, n);
    const Eigen::Isometry3d cam_from_obj =
        rigid(r, matrix4(r, r.member(objects[i], path, "pose"), Reader::join(path, "pose")), Reader::join(path, "pose"),
              0.01);
    const std::string bpath = Reader::join(path, "bbox3d");
    const json& bb = r.array(r.member(objects[i], path, "bbox3d"), bpath);
    if (bb.size() != 6) r.fail(bpath, fmt::format("expected 6 numbers, got {}", bb.size()));
    Eigen::Vector3d lo, hi;
    for (int a = 0; a < 3; ++a) {
      lo[a] = 0.01 * r.number(bb[static_cast<std::size_t>(a)], Reader::index(bpath, static_cast<std::size_t>(a)));
      hi[a] = 0.01 * r.number(bb[static_cast<std::size_t>(a + 3)], Reader::index(bpath, static_cast<std::size_t>(a + 3)));
      if (!(hi[a] > lo[a])) r.fail(bpath, fmt::format("max must exceed min on axis {}", a));
    }
    o.size = hi - lo;
    Eigen::Isometry3d obj_from_obb = Eigen::Isometry3d::Identity();
    obj_from_obb.translation() = 0.5 * (lo + hi);
    o.world_from_obb = world_from_cam * cam_from_obj * obj_from_obb;
    raw.push_back(o);
  }

  // Table height and origin in the world frame.
  std::vector<double> zmin;
  Eigen::Vector2d mean_xy = Eigen::Vector2d::Zero();
  for (const auto& o : raw) {
    zmin.push_back(Obb::from_pose(Pose::from_isometry(o.world_from_obb), o.size).min_z());
    mean_xy += o.world_from_obb.translation().head<2>();
  }
  mean_xy /= static_cast<double>(raw.size());
  std::sort(zmin.begin(), zmin.end());
  const std::size_t m = zmin.size();
  const double median = m % 2 ? zmin[m / 2] : 0.5 * (zmin[m / 2 - 1] + zmin[m / 2]);
  out.table_z_world = options.table_z_world.value_or(median);

  Eigen::Isometry3d world_from_table = Eigen::Isometry3d::Identity();
  world_from_table.translation() = Eigen::Vector3d(mean_xy.x(), mean_xy.y(), out.table_z_world);
  const Eigen::Isometry3d table_from_world = world_from_table.inverse();
  s.table_in_camera = Pose::from_isometry(world_from_cam.inverse() * world_from_table);
  s.table.size = options.table_size;
  for (const auto& o : raw) {
    SceneObject so;
    so.id = o.id;
    so.model = o.model;
    so.size = o.size;
    so.pose = Pose::from_isometry(table_from_world * o.world_from_obb);
    s.objects.push_back(so);
  }
  return out;
}

HopeImport import_hope_file(const std::filesystem::path& path, const HopeImportOptions& options) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(fmt::format("{}: cannot open file", name));
  std::stringstream buf;
  buf << in.rdbuf();
  json doc;
  const std::string text = buf.str();
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for 1e999
    throw SceneError(ksmc::runtime::io::json_error_message(name, text, e));
  }
  return import_hope(doc, name, options);
}

}  // namespace ksmc::stdlib::tabletop
