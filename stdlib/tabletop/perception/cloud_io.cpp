#include "stdlib/tabletop/perception/cloud_io.h"

#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "runtime/io/atomic_file.h"

namespace ksmc::stdlib::tabletop::perception {

Units parse_units(std::string_view text) {
  if (text == "m") return Units::m;
  if (text == "cm") return Units::cm;
  if (text == "mm") return Units::mm;
  throw std::invalid_argument(fmt::format("unknown cloud unit \"{}\" (expected cm, mm or m)", text));
}

double metres_per_unit(Units units) {
  switch (units) {
    case Units::cm: return 0.01;
    case Units::mm: return 0.001;
    case Units::m: break;
  }
  return 1.0;
}

Points load_cloud(const std::filesystem::path& path, Units units) {
  const std::string name = path.string();
  if (!std::ifstream(path, std::ios::binary)) throw CloudError(fmt::format("{}: cannot open file", name));
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".ply" && ext != ".pcd")
    throw CloudError(fmt::format("{}: unknown cloud format \"{}\" (expected .ply or .pcd)", name, ext));

  // PCL reports its own parse errors on stderr; ours name the file, so silence it.
  const auto verbosity = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  int rc = -1;
  try {
    rc = ext == ".ply" ? pcl::io::loadPLYFile(name, cloud) : pcl::io::loadPCDFile(name, cloud);
  } catch (const std::exception& e) {
    pcl::console::setVerbosityLevel(verbosity);
    throw CloudError(fmt::format("{}: cannot parse point cloud: {}", name, e.what()));
  }
  pcl::console::setVerbosityLevel(verbosity);
  if (rc < 0) throw CloudError(fmt::format("{}: cannot parse point cloud ({} reader failed)", name, ext));
  if (cloud.empty()) throw CloudError(fmt::format("{}: empty cloud: no points", name));

  const double scale = metres_per_unit(units);
  Points out;
  out.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw CloudError(fmt::format("{}: point {}: not a finite coordinate ({}, {}, {})", name, i, p.x, p.y, p.z));
    out.emplace_back(scale * p.x, scale * p.y, scale * p.z);
  }
  return out;
}

std::string ply_text(const Points& points) {
  std::string s = fmt::format(
      "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
      points.size());
  for (const auto& p : points) s += fmt::format("{:.6f} {:.6f} {:.6f}\n", p.x(), p.y(), p.z());
  return s;
}

void save_ply(const std::filesystem::path& path, const Points& points) {
  runtime::io::write_file_atomic(path, ply_text(points));
}

}  // namespace ksmc::stdlib::tabletop::perception
