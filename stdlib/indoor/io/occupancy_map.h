// A loaded occupancy grid: the classified map C_M of seed eq. 3.7 plus its metric frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

// Limits enforced by every loader (documented in the error messages).
// A map must be at least 3 cells along each side (wall, free, wall) ...
inline constexpr int kMinMapSide = 3;
// ... and at most 2.5e8 cells (about 40 km^2 at 0.05 m): refused from the header, before decoding.
inline constexpr std::int64_t kMaxMapCells = 250'000'000;

// ROS map_server interpretation modes.
enum class MapMode { Trinary, Scale, Raw };

// How grey values become cell classes (map_server semantics):
//   trinary/scale: p = (255 - v) / 255 (v inverted first when `negate`),
//                  occupied if p > occupied_thresh, free if p < free_thresh, else unknown;
//                  scale differs from trinary only in the grey levels it gives cells between the
//                  thresholds; with three classes both give unknown there, so they classify alike.
//   raw:           v is an occupancy value in percent: p = v / 100 for v <= 100, same thresholds;
//                  v > 100 (e.g. 255 = -1 as int8) is unknown.
struct Thresholds {
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  bool negate = false;
  MapMode mode = MapMode::Trinary;

  // Only with painted_unknown: grey values between the thresholds are occupied (drawn walls,
  // furniture), except the most frequent of them when it covers at least kPaintShare of the
  // image: that is the paint of unexplored space and stays unknown.
  bool painted_unknown = false;

  // The Bormann/IPA benchmark convention: a pixel is free iff its value is >= 250,
  // everything darker is occupied (no unknown class).
  static Thresholds bormann();
  // The default for bare images (no YAML): >= 250 free (the benchmark convention; map_saver
  // writes 254), map_server's dark threshold (p > 0.65) occupied, and the greys between
  // by painted_unknown. Drawn floor plans (grey walls on a grey outside) and SLAM images (one
  // light grey for unexplored space) both read right.
  static Thresholds drawn();
  // By the names of the indoor binary's --thresholds: drawn, strict (>= 250 free, map_server's
  // dark threshold occupied, else unknown: SLAM images), ros (map_server) or bormann; nullopt
  // for any other name.
  static std::optional<Thresholds> by_name(const std::string& name);
};

// The share of the image the unexplored-space paint must cover (Thresholds::painted_unknown).
inline constexpr double kPaintShare = 0.05;

struct Pose2 {
  double x = 0.0;    // m, world position of the lower-left pixel (map_server convention)
  double y = 0.0;    // m
  double yaw = 0.0;  // rad
};

struct ClassCounts {
  std::size_t free = 0;
  std::size_t unknown = 0;
  std::size_t occupied = 0;
  std::size_t total() const { return free + unknown + occupied; }
};

struct OccupancyMap {
  ClassGrid grid;                 // Cell values, row 0 = top row of the image
  cv::Mat1b intensity;            // the grey values the classes came from (after channel averaging,
                                  // before negate), same size as grid
  double resolution = 0.05;       // m per cell
  Pose2 origin;                   // map_server origin
  Thresholds thresholds;          // what was used to classify
  std::filesystem::path source;   // YAML file if loaded from one, else the image
  std::filesystem::path image;    // the image file actually decoded
  std::vector<std::string> warnings;  // non-fatal findings (e.g. resolution conflicts)

  int rows() const { return grid.rows; }
  int cols() const { return grid.cols; }
  ClassCounts counts() const;
};

ClassCounts count_classes(const ClassGrid& grid);

// Classifies one grey value (0..255, before negate) with map_server semantics.
Cell classify_value(std::uint8_t value, const Thresholds& t);

// Classifies a whole grey image (with painted_unknown: by the image's own grey histogram).
ClassGrid classify_image(const cv::Mat1b& grey, const Thresholds& t);

}  // namespace ksmc::stdlib::indoor::io
