#include "ros/io/indoor_messages.h"

#include <fstream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "ros/io/map_frame.h"

namespace ksmc::ros_io {

namespace {

std_msgs::ColorRGBA type_color(const std::string& type) {
  static const std::map<std::string, std::array<float, 3>> kColors = {
      {"room", {0.31F, 0.47F, 0.65F}}, {"corridor", {0.95F, 0.56F, 0.17F}}, {"hall", {0.35F, 0.63F, 0.31F}}};
  const auto it = kColors.find(type);
  const auto rgb = it == kColors.end() ? std::array<float, 3>{0.69F, 0.48F, 0.63F} : it->second;
  std_msgs::ColorRGBA c;
  c.r = rgb[0];
  c.g = rgb[1];
  c.b = rgb[2];
  c.a = 1.0F;
  return c;
}

visualization_msgs::Marker marker(const std_msgs::Header& h, const std::string& ns, int id, int type) {
  visualization_msgs::Marker m;
  m.header = h;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  return m;
}

nlohmann::json xy(const geometry_msgs::Point& p) { return {p.x, p.y}; }

nlohmann::json read_world(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": missing (the indoor run wrote no world.json)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

}  // namespace

IndoorMessages indoor_messages(const std::filesystem::path& out_dir, const nav_msgs::OccupancyGrid& map) {
  const nlohmann::json world = read_world(out_dir / "world.json");
  if (world.at("map").at("width") != map.info.width || world.at("map").at("height") != map.info.height) {
    throw std::runtime_error((out_dir / "world.json").string() + ": map size differs from the published grid");
  }
  const MapFrame frame(map.info);
  IndoorMessages out;
  std_msgs::Header h = map.header;
  if (h.frame_id.empty()) h.frame_id = "map";  // RViz drops markers without a frame
  const double line = frame.metres(2.0) > 0.05 ? frame.metres(2.0) : 0.05;

  visualization_msgs::Marker clear;
  clear.header = h;
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.markers.push_back(clear);

  nlohmann::json units = nlohmann::json::array();
  nlohmann::json table = nlohmann::json::array();
  std::map<int, std::size_t> cells;
  for (const auto& u : world.at("units")) {
    const int id = u.at("id");
    const std::string type = u.at("type");
    auto outline = marker(h, "units", id, visualization_msgs::Marker::LINE_STRIP);
    outline.scale.x = line;
    outline.color = type_color(type);
    double cx = 0, cy = 0;
    nlohmann::json corners = nlohmann::json::array();
    const auto& cs = u.at("corners");
    for (std::size_t k = 0; k <= cs.size(); ++k) {
      const auto& c = cs[k % cs.size()];
      const geometry_msgs::Point p = frame.point(c[0].get<double>(), c[1].get<double>());
      outline.points.push_back(p);
      if (k < cs.size()) {
        cx += p.x / static_cast<double>(cs.size());
        cy += p.y / static_cast<double>(cs.size());
        corners.push_back(xy(p));
      }
    }
    out.markers.markers.push_back(outline);
    auto text = marker(h, "labels", id, visualization_msgs::Marker::TEXT_VIEW_FACING);
    text.pose.position.x = cx;
    text.pose.position.y = cy;
    text.pose.position.z = 0.5;
    text.scale.z = 0.5;
    text.color = type_color(type);
    text.text = type + " " + std::to_string(id);
    out.markers.markers.push_back(text);
    const auto side = [&](std::size_t a, std::size_t b) {
      return std::hypot(corners[b][0].get<double>() - corners[a][0].get<double>(), corners[b][1].get<double>() - corners[a][1].get<double>());
    };
    units.push_back({{"id", id}, {"type", type}, {"type_probs", u.value("type_probs", nlohmann::json::object())},
                     {"centre", {cx, cy}}, {"size", {side(0, 1), side(1, 2)}}, {"corners", corners}});
    cells[id] = 0;
  }
  nlohmann::json doors = nlohmann::json::array();
  for (const auto& d : world.at("doors")) {
    const int id = d.at("id");
    auto m = marker(h, "doors", id, visualization_msgs::Marker::LINE_STRIP);
    m.scale.x = 2.0 * line;
    m.color.r = 0.84F;
    m.color.g = 0.15F;
    m.color.b = 0.16F;
    m.color.a = 1.0F;
    nlohmann::json seg = nlohmann::json::array();
    for (const auto& e : d.at("segment")) {
      const geometry_msgs::Point p = frame.point(e[0].get<double>(), e[1].get<double>(), 0.05);
      m.points.push_back(p);
      seg.push_back(xy(p));
    }
    out.markers.markers.push_back(m);
    doors.push_back({{"id", id}, {"units", d.at("units")}, {"segment", seg}});
  }
  out.units = units.size();
  out.doors = doors.size();

  // Segmentation from labels.png (16-bit unit ids, image rows top-down).
  const auto labels_path = out_dir / "labels.png";
  const cv::Mat labels = cv::imread(labels_path.string(), cv::IMREAD_UNCHANGED);
  if (labels.empty()) throw std::runtime_error(labels_path.string() + ": missing or unreadable");
  if (labels.type() != CV_16UC1 || labels.cols != static_cast<int>(map.info.width) || labels.rows != static_cast<int>(map.info.height)) {
    throw std::runtime_error(labels_path.string() + ": expected a 16-bit image of the map's size");
  }
  out.segmentation.header = h;
  out.segmentation.info = map.info;
  out.segmentation.data.assign(map.data.size(), -1);
  for (int r = 0; r < labels.rows; ++r) {
    for (int c = 0; c < labels.cols; ++c) {
      const int id = labels.at<std::uint16_t>(labels.rows - 1 - r, c);
      if (id == 0) continue;
      out.segmentation.data[static_cast<std::size_t>(r) * map.info.width + static_cast<std::size_t>(c)] = static_cast<std::int8_t>(id % 100);
      ++cells[id];
    }
  }
  for (const auto& u : units) {
    const int id = u.at("id");
    table.push_back({{"id", id}, {"value", id % 100}, {"type", u.at("type")}, {"cells", cells[id]}});
  }
  out.id_table = nlohmann::json{{"modulo", 100}, {"none", -1}, {"units", table}}.dump();
  out.scene_graph = nlohmann::json{{"frame_id", h.frame_id},
                                   {"stamp", h.stamp.toSec()},
                                   {"units", units},
                                   {"doors", doors},
                                   {"adjacent", world.at("adjacent")},
                                   {"metrics", world.value("metrics", nlohmann::json::object())}}
                        .dump();
  return out;
}

}  // namespace ksmc::ros_io
