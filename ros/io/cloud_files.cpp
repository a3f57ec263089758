#include "ros/io/cloud_files.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <sensor_msgs/PointField.h>

namespace ksmc::ros_io {

namespace {

std::uint32_t float_field_offset(const sensor_msgs::PointCloud2& cloud, const std::string& name) {
  for (const auto& f : cloud.fields) {
    if (f.name != name) continue;
    if (f.datatype != sensor_msgs::PointField::FLOAT32 || f.count < 1)
      throw std::runtime_error("point cloud field '" + name + "' is not FLOAT32 (datatype " +
                               std::to_string(static_cast<int>(f.datatype)) + ")");
    if (f.offset + sizeof(float) > cloud.point_step)
      throw std::runtime_error("point cloud field '" + name + "' (offset " + std::to_string(f.offset) +
                               ") lies outside point_step " + std::to_string(cloud.point_step));
    return f.offset;
  }
  std::string names;
  for (const auto& f : cloud.fields) names += (names.empty() ? "" : ", ") + f.name;
  throw std::runtime_error("point cloud has no field '" + name + "' (fields: " + (names.empty() ? "none" : names) + ")");
}

float read_float(const std::uint8_t* at) {
  float v = 0.0F;
  std::memcpy(&v, at, sizeof v);
  return v;
}

}  // namespace

std::vector<std::array<float, 3>> cloud_points(const sensor_msgs::PointCloud2& cloud) {
  if (cloud.is_bigendian) throw std::runtime_error("big-endian point clouds are not supported");
  const std::uint32_t ox = float_field_offset(cloud, "x"), oy = float_field_offset(cloud, "y"),
                      oz = float_field_offset(cloud, "z");
  if (std::uint64_t{cloud.width} * cloud.point_step > cloud.row_step)
    throw std::runtime_error("point cloud rows overrun row_step: width " + std::to_string(cloud.width) + " x point_step " +
                             std::to_string(cloud.point_step) + " > " + std::to_string(cloud.row_step));
  if (std::uint64_t{cloud.height} * cloud.row_step > cloud.data.size())
    throw std::runtime_error("point cloud data holds " + std::to_string(cloud.data.size()) + " bytes, height " +
                             std::to_string(cloud.height) + " x row_step " + std::to_string(cloud.row_step) + " needed");
  std::vector<std::array<float, 3>> out;
  out.reserve(std::size_t{cloud.width} * cloud.height);
  for (std::uint32_t row = 0; row < cloud.height; ++row) {
    const std::uint8_t* base = cloud.data.data() + std::size_t{row} * cloud.row_step;
    for (std::uint32_t col = 0; col < cloud.width; ++col, base += cloud.point_step) {
      const std::array<float, 3> p = {read_float(base + ox), read_float(base + oy), read_float(base + oz)};
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) out.push_back(p);
    }
  }
  return out;
}

void write_pcd(const std::filesystem::path& path, const std::vector<std::array<float, 3>>& points) {
  if (points.empty()) throw std::runtime_error(path.string() + ": no finite point to write");
  std::ofstream out(path, std::ios::binary);
  const std::string n = std::to_string(points.size());
  out << "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n"
      << "COUNT 1 1 1\nWIDTH " << n << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n << "\nDATA binary\n";
  static_assert(sizeof(std::array<float, 3>) == 3 * sizeof(float));
  out.write(reinterpret_cast<const char*>(points.data()),
            static_cast<std::streamsize>(points.size() * sizeof(std::array<float, 3>)));
  out.close();
  if (!out) throw std::runtime_error(path.string() + ": cannot write the point cloud");
}

sensor_msgs::PointCloud2 xyz_cloud(const std::vector<std::array<float, 3>>& points, const std::string& frame) {
  sensor_msgs::PointCloud2 c;
  c.header.frame_id = frame;
  const char* names[] = {"x", "y", "z"};
  for (std::uint32_t i = 0; i < 3; ++i) {
    sensor_msgs::PointField f;
    f.name = names[i];
    f.offset = i * 4;
    f.datatype = sensor_msgs::PointField::FLOAT32;
    f.count = 1;
    c.fields.push_back(f);
  }
  c.point_step = 16;
  c.height = 1;
  c.width = static_cast<std::uint32_t>(points.size());
  c.row_step = c.width * c.point_step;
  c.is_bigendian = false;
  c.is_dense = true;
  c.data.assign(c.row_step, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::memcpy(c.data.data() + i * c.point_step, points[i].data(), 3 * sizeof(float));
    c.is_dense = c.is_dense && std::isfinite(points[i][0]) && std::isfinite(points[i][1]) && std::isfinite(points[i][2]);
  }
  return c;
}

}  // namespace ksmc::ros_io
