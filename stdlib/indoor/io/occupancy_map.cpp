#include "stdlib/indoor/io/occupancy_map.h"

#include <cstddef>

namespace ksmc::stdlib::indoor::io {

Thresholds Thresholds::bormann() {
  Thresholds t;
  // v >= 250  <=>  p = (255 - v)/255 <= 5/255 < 5.5/255; anything darker has p >= 6/255.
  t.free_thresh = 5.5 / 255.0;
  t.occupied_thresh = 5.5 / 255.0;
  t.negate = false;
  t.mode = MapMode::Trinary;
  return t;
}

Thresholds Thresholds::drawn() {
  Thresholds t;
  t.free_thresh = 5.5 / 255.0;
  t.painted_unknown = true;
  return t;
}

std::optional<Thresholds> Thresholds::by_name(const std::string& name) {
  if (name == "bormann") return bormann();
  if (name == "drawn") return drawn();
  if (name == "ros") return Thresholds{};
  if (name == "strict") {
    Thresholds t;
    t.free_thresh = 5.5 / 255.0;
    return t;
  }
  return std::nullopt;
}

ClassCounts count_classes(const ClassGrid& grid) {
  ClassCounts c;
  for (int r = 0; r < grid.rows; ++r) {
    const std::uint8_t* row = grid.ptr<std::uint8_t>(r);
    for (int col = 0; col < grid.cols; ++col) {
      switch (static_cast<Cell>(row[col])) {
        case Cell::Free: ++c.free; break;
        case Cell::Unknown: ++c.unknown; break;
        case Cell::Occupied: ++c.occupied; break;
      }
    }
  }
  return c;
}

ClassCounts OccupancyMap::counts() const { return count_classes(grid); }

namespace {

// Returns occupancy probability p in [0,1], or a negative number for "unknown by value" (raw > 100).
double occupancy_of(std::uint8_t value, const Thresholds& t) {
  const double v = t.negate ? 255.0 - value : static_cast<double>(value);
  if (t.mode == MapMode::Raw) {
    if (v > 100.0) return -1.0;
    return v / 100.0;
  }
  return (255.0 - v) / 255.0;
}

}  // namespace

Cell classify_value(std::uint8_t value, const Thresholds& t) {
  const double p = occupancy_of(value, t);
  if (p < 0.0) return Cell::Unknown;
  if (p > t.occupied_thresh) return Cell::Occupied;
  if (p < t.free_thresh) return Cell::Free;
  return Cell::Unknown;
}

ClassGrid classify_image(const cv::Mat1b& grey, const Thresholds& t) {
  // A 256-entry lookup table keeps this exact and fast on large maps.
  std::uint8_t lut[256];
  for (int v = 0; v < 256; ++v) {
    lut[v] = static_cast<std::uint8_t>(classify_value(static_cast<std::uint8_t>(v), t));
  }
  if (t.painted_unknown) {
    std::size_t hist[256] = {};
    for (int r = 0; r < grey.rows; ++r) {
      const std::uint8_t* in = grey.ptr<std::uint8_t>(r);
      for (int c = 0; c < grey.cols; ++c) ++hist[in[c]];
    }
    int paint = -1;  // the most frequent grey between the thresholds (ties: the lighter)
    for (int v = 0; v < 256; ++v) {
      if (lut[v] != static_cast<std::uint8_t>(Cell::Unknown)) continue;
      if (paint < 0 || hist[v] >= hist[paint]) paint = v;
    }
    const bool painted = paint >= 0 && static_cast<double>(hist[paint]) >= kPaintShare * static_cast<double>(grey.total());
    for (int v = 0; v < 256; ++v)
      if (lut[v] == static_cast<std::uint8_t>(Cell::Unknown) && !(painted && v == paint))
        lut[v] = static_cast<std::uint8_t>(Cell::Occupied);
  }
  ClassGrid out(grey.rows, grey.cols);
  for (int r = 0; r < grey.rows; ++r) {
    const std::uint8_t* in = grey.ptr<std::uint8_t>(r);
    std::uint8_t* o = out.ptr<std::uint8_t>(r);
    for (int c = 0; c < grey.cols; ++c) o[c] = lut[in[c]];
  }
  return out;
}

}  // namespace ksmc::stdlib::indoor::io
