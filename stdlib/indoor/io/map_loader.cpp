#include "stdlib/indoor/io/map_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "stdlib/indoor/io/image_file.h"
#include "stdlib/indoor/io/map_error.h"

namespace ksmc::stdlib::indoor::io {

namespace fs = std::filesystem;

namespace {

int line_of(const YAML::Node& n) {
  const YAML::Mark m = n.Mark();
  return m.line >= 0 ? m.line + 1 : 0;
}

double yaml_number(const fs::path& file, const YAML::Node& n, const char* key) {
  if (!n.IsScalar()) {
    throw MapLoadError(MapErrorKind::YamlBadValue, file, line_of(n),
                       fmt::format("'{}' must be a number", key));
  }
  double v = 0.0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    throw MapLoadError(MapErrorKind::YamlBadValue, file, line_of(n),
                       fmt::format("'{}' must be a number, got '{}'", key, n.Scalar()));
  }
  if (!std::isfinite(v)) {
    throw MapLoadError(MapErrorKind::YamlBadValue, file, line_of(n),
                       fmt::format("'{}' must be a finite number, got '{}'", key, n.Scalar()));
  }
  return v;
}

bool resolutions_differ(double a, double b) { return std::fabs(a - b) > 1e-9 * std::max(a, b); }

void check_thresholds(const fs::path& file, int line, const Thresholds& t) {
  if (!(t.free_thresh >= 0.0 && t.occupied_thresh <= 1.0 && t.free_thresh <= t.occupied_thresh)) {
    throw MapLoadError(MapErrorKind::YamlBadValue, file, line,
                       fmt::format("thresholds must satisfy 0 <= free_thresh ({}) <= "
                                   "occupied_thresh ({}) <= 1",
                                   t.free_thresh, t.occupied_thresh));
  }
}

// Decodes, classifies and validates; `context` is appended to image error messages.
// `header_res` receives the resolution written in the image header comment, if any.
OccupancyMap build_map(const fs::path& image, const Thresholds& t, const std::string& context,
                       std::optional<double>* header_res) {
  GreyImage img;
  try {
    img = read_grey_image(image);
  } catch (const MapLoadError& e) {
    if (context.empty()) throw;
    // Re-throw with the referencing YAML named, keeping the kind and the image as the file.
    const std::string what = e.what();
    const std::string prefix = e.file().string() + ": error: ";
    const std::string msg = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
    throw MapLoadError(e.kind(), e.file(), e.line(), msg + " (" + context + ")");
  }
  OccupancyMap m;
  m.intensity = img.grey;
  m.grid = classify_image(img.grey, t);
  m.thresholds = t;
  m.image = image;
  const ClassCounts c = count_classes(m.grid);
  if (c.free == 0) {
    throw MapLoadError(
        MapErrorKind::NoFreeCells, image, 0,
        fmt::format("map has no free cells ({} occupied, {} unknown of {}x{}) with "
                    "free_thresh {} / occupied_thresh {} / negate {}; check the thresholds and "
                    "'negate'",
                    c.occupied, c.unknown, m.grid.cols, m.grid.rows, t.free_thresh,
                    t.occupied_thresh, t.negate ? 1 : 0) +
            (context.empty() ? std::string() : " (" + context + ")"));
  }
  *header_res = img.header.comment_resolution;
  return m;
}

// Plausible metres per cell: 0.1 mm to 1 km. Outside, a typo (1e-300, 1e300) would reach
// the detectors as absurd cell counts instead of a message naming the file.
constexpr double kMinResolution = 1e-4;
constexpr double kMaxResolution = 1e3;

void check_resolution_option(const fs::path& file, double r) {
  if (!(r > 0.0) || !std::isfinite(r)) {
    throw MapLoadError(MapErrorKind::BadOption, file, 0,
                       fmt::format("resolution must be a positive number of metres per cell, got {}",
                                   r));
  }
  if (r < kMinResolution || r > kMaxResolution) {
    throw MapLoadError(MapErrorKind::BadOption, file, 0,
                       fmt::format("resolution {} metres per cell is outside the plausible range [{}, {}]", r,
                                   kMinResolution, kMaxResolution));
  }
}

}  // namespace

OccupancyMap load_map_yaml(const fs::path& yaml, const YamlLoadOptions& opts) {
  if (opts.resolution_override) check_resolution_option(yaml, *opts.resolution_override);
  const std::string text = read_file_bytes(yaml);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw MapLoadError(MapErrorKind::YamlSyntax, yaml, e.mark.line >= 0 ? e.mark.line + 1 : 0,
                       "YAML syntax error: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw MapLoadError(MapErrorKind::YamlSyntax, yaml, 0, std::string("YAML error: ") + e.what());
  }
  if (!root.IsMap()) {
    throw MapLoadError(MapErrorKind::YamlBadValue, yaml, root.IsDefined() ? line_of(root) : 1,
                       "expected a map_server YAML mapping with 'image' and 'resolution' keys");
  }
  const YAML::Node image_node = root["image"];
  if (!image_node) {
    throw MapLoadError(MapErrorKind::YamlMissingKey, yaml, 0, "required key 'image' is missing");
  }
  if (!image_node.IsScalar() || image_node.Scalar().empty()) {
    throw MapLoadError(MapErrorKind::YamlBadValue, yaml, line_of(image_node),
                       "'image' must be a file name");
  }
  const YAML::Node res_node = root["resolution"];
  if (!res_node) {
    throw MapLoadError(MapErrorKind::YamlMissingKey, yaml, 0,
                       "required key 'resolution' (metres per cell) is missing");
  }
  const double yaml_res = yaml_number(yaml, res_node, "resolution");
  if (!(yaml_res > 0.0)) {
    throw MapLoadError(MapErrorKind::YamlBadValue, yaml, line_of(res_node),
                       fmt::format("'resolution' must be positive, got {}", yaml_res));
  }
  if (yaml_res < kMinResolution || yaml_res > kMaxResolution) {
    throw MapLoadError(MapErrorKind::YamlBadValue, yaml, line_of(res_node),
                       fmt::format("'resolution' {} metres per cell is outside the plausible range [{}, {}]",
                                   res_node.Scalar(), kMinResolution, kMaxResolution));
  }

  Thresholds t;
  int thresh_line = 0;
  if (const YAML::Node n = root["occupied_thresh"]) {
    t.occupied_thresh = yaml_number(yaml, n, "occupied_thresh");
    thresh_line = line_of(n);
  }
  if (const YAML::Node n = root["free_thresh"]) {
    t.free_thresh = yaml_number(yaml, n, "free_thresh");
    thresh_line = line_of(n);
  }
  check_thresholds(yaml, thresh_line, t);
  if (const YAML::Node n = root["negate"]) {
    bool neg = false;
    if (n.IsScalar() && (n.Scalar() == "0" || n.Scalar() == "1")) {
      neg = n.Scalar() == "1";
    } else {
      try {
        neg = n.as<bool>();
      } catch (const YAML::Exception&) {
        throw MapLoadError(MapErrorKind::YamlBadValue, yaml, line_of(n),
                           "'negate' must be 0, 1, true or false");
      }
    }
    t.negate = neg;
  }
  if (const YAML::Node n = root["mode"]) {
    const std::string s = n.IsScalar() ? n.Scalar() : std::string();
    if (s == "trinary") {
      t.mode = MapMode::Trinary;
    } else if (s == "scale") {
      t.mode = MapMode::Scale;
    } else if (s == "raw") {
      t.mode = MapMode::Raw;
    } else {
      throw MapLoadError(MapErrorKind::YamlBadValue, yaml, line_of(n),
                         "'mode' must be trinary, scale or raw, got '" + s + "'");
    }
  }
  Pose2 origin;
  if (const YAML::Node n = root["origin"]) {
    if (!n.IsSequence() || n.size() < 2 || n.size() > 3) {
      throw MapLoadError(MapErrorKind::YamlBadValue, yaml, line_of(n),
                         "'origin' must be a list [x, y, yaw]");
    }
    origin.x = yaml_number(yaml, n[0], "origin[0]");
    origin.y = yaml_number(yaml, n[1], "origin[1]");
    if (n.size() == 3) origin.yaw = yaml_number(yaml, n[2], "origin[2]");
  }

  fs::path image = image_node.Scalar();
  if (image.is_relative()) image = yaml.parent_path() / image;
  const std::string context =
      fmt::format("image referenced from {}:{}", yaml.string(), line_of(image_node));
  std::optional<double> header_res;
  OccupancyMap m = build_map(image, t, context, &header_res);
  m.source = yaml;
  m.origin = origin;
  m.resolution = opts.resolution_override.value_or(yaml_res);
  if (header_res && resolutions_differ(*header_res, yaml_res)) {
    m.warnings.push_back(fmt::format(
        "{}:{}: warning: resolution conflict: the YAML says {} m/cell but the header of {} says "
        "{} m/pix; using {} ({})",
        yaml.string(), line_of(res_node), yaml_res, image.string(), *header_res, m.resolution,
        opts.resolution_override ? "given by the caller" : "from the YAML; override with --resolution"));
  }
  if (opts.resolution_override && resolutions_differ(*opts.resolution_override, yaml_res)) {
    m.warnings.push_back(fmt::format("{}:{}: warning: resolution {} from the YAML overridden by {}",
                                     yaml.string(), line_of(res_node), yaml_res,
                                     *opts.resolution_override));
  }
  return m;
}

OccupancyMap load_map_image(const fs::path& image, const ImageLoadOptions& opts) {
  if (opts.resolution) check_resolution_option(image, *opts.resolution);
  if (!(opts.thresholds.free_thresh >= 0.0 && opts.thresholds.occupied_thresh <= 1.0 &&
        opts.thresholds.free_thresh <= opts.thresholds.occupied_thresh)) {
    throw MapLoadError(MapErrorKind::BadOption, image, 0,
                       fmt::format("thresholds must satisfy 0 <= free_thresh ({}) <= "
                                   "occupied_thresh ({}) <= 1",
                                   opts.thresholds.free_thresh, opts.thresholds.occupied_thresh));
  }
  std::optional<double> header_res;
  OccupancyMap m = build_map(image, opts.thresholds, std::string(), &header_res);
  m.source = image;
  m.origin = opts.origin;
  m.resolution = opts.resolution.value_or(header_res.value_or(0.05));
  if (opts.resolution && header_res && resolutions_differ(*header_res, *opts.resolution)) {
    m.warnings.push_back(fmt::format(
        "{}: warning: resolution conflict: the image header says {} m/pix; using {} given by the "
        "caller",
        image.string(), *header_res, *opts.resolution));
  }
  return m;
}

OccupancyMap load_map(const fs::path& path, const ImageLoadOptions& opts) {
  std::string ext = path.extension().string();
  for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (ext == ".yaml" || ext == ".yml") {
    YamlLoadOptions y;
    y.resolution_override = opts.resolution;
    return load_map_yaml(path, y);
  }
  return load_map_image(path, opts);
}

}  // namespace ksmc::stdlib::indoor::io
