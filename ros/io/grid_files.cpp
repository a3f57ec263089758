#include "ros/io/grid_files.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <yaml-cpp/yaml.h>

namespace ksmc::ros_io {

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

std::filesystem::path write_map_files(const nav_msgs::OccupancyGrid& grid, const std::filesystem::path& dir,
                                      const std::string& stem, const GridThresholds& t) {
  const auto w = static_cast<int>(grid.info.width), h = static_cast<int>(grid.info.height);
  if (w <= 0 || h <= 0) throw std::runtime_error("occupancy grid: empty (" + std::to_string(w) + "x" + std::to_string(h) + ")");
  if (grid.data.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {
    throw std::runtime_error("occupancy grid: " + std::to_string(grid.data.size()) + " cells for " + std::to_string(w) + "x" +
                             std::to_string(h));
  }
  if (!(grid.info.resolution > 0.0F)) throw std::runtime_error("occupancy grid: resolution must be positive");
  std::filesystem::create_directories(dir);
  cv::Mat1b img(h, w);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const int v = grid.data[static_cast<std::size_t>(r) * static_cast<std::size_t>(w) + static_cast<std::size_t>(c)];
      unsigned char px = 205;
      if (v >= 0 && v >= t.occupied * 100.0) px = 0;
      else if (v >= 0 && v <= t.free * 100.0) px = 254;
      img(h - 1 - r, c) = px;
    }
  }
  const auto pgm = dir / (stem + ".pgm");
  if (!cv::imwrite(pgm.string(), img)) throw std::runtime_error(pgm.string() + ": cannot write");
  const auto yaml = dir / (stem + ".yaml");
  std::ofstream y(yaml);
  // Shortest round-trip forms: the grid's float resolution prints as 0.05, not 0.0500000007.
  y << fmt::format("image: {}.pgm\nresolution: {}\norigin: [{}, {}, {}]\nnegate: 0\noccupied_thresh: {}\nfree_thresh: {}\n", stem,
                   grid.info.resolution, grid.info.origin.position.x, grid.info.origin.position.y,
                   yaw_of(grid.info.origin.orientation), t.occupied, t.free);
  if (!y) throw std::runtime_error(yaml.string() + ": cannot write");
  return yaml;
}

nav_msgs::OccupancyGrid read_map_files(const std::filesystem::path& yaml) {
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(yaml.string());
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml.string() + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  for (const char* key : {"image", "resolution", "origin"})
    if (!doc[key]) throw std::runtime_error(yaml.string() + ": missing '" + key + "'");
  const auto image = yaml.parent_path() / doc["image"].as<std::string>();
  const double res = doc["resolution"].as<double>();
  const auto origin = doc["origin"].as<std::vector<double>>();
  if (!(res > 0.0)) throw std::runtime_error(yaml.string() + ": resolution must be positive");
  if (origin.size() != 3) throw std::runtime_error(yaml.string() + ": origin must be [x, y, yaw]");
  const bool negate = doc["negate"] && doc["negate"].as<int>() != 0;
  const double occ = doc["occupied_thresh"] ? doc["occupied_thresh"].as<double>() : 0.65;
  const double fre = doc["free_thresh"] ? doc["free_thresh"].as<double>() : 0.196;
  const cv::Mat img = cv::imread(image.string(), cv::IMREAD_GRAYSCALE);
  if (img.empty()) throw std::runtime_error(image.string() + ": cannot read the map image");
  nav_msgs::OccupancyGrid g;
  g.header.frame_id = "map";
  g.info.resolution = static_cast<float>(res);
  g.info.width = static_cast<std::uint32_t>(img.cols);
  g.info.height = static_cast<std::uint32_t>(img.rows);
  g.info.origin.position.x = origin[0];
  g.info.origin.position.y = origin[1];
  g.info.origin.orientation.z = std::sin(origin[2] / 2.0);
  g.info.origin.orientation.w = std::cos(origin[2] / 2.0);
  g.data.resize(static_cast<std::size_t>(img.cols) * static_cast<std::size_t>(img.rows));
  for (int r = 0; r < img.rows; ++r) {
    for (int c = 0; c < img.cols; ++c) {
      const double v = img.at<unsigned char>(img.rows - 1 - r, c);
      const double p = negate ? v / 255.0 : (255.0 - v) / 255.0;  // map_server: occupancy probability
      const std::int8_t cell = p > occ ? 100 : (p < fre ? 0 : -1);
      g.data[static_cast<std::size_t>(r) * static_cast<std::size_t>(img.cols) + static_cast<std::size_t>(c)] = cell;
    }
  }
  return g;
}

}  // namespace ksmc::ros_io
