#include "stdlib/indoor/io/world_images.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/label_placement.h"
#include "stdlib/indoor/io/type_style.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr int kShift = 4;  // sub-pixel bits for OpenCV drawing
constexpr double kOne = 1 << kShift;

// Cell coordinate -> fixed-point pixel coordinate in an image upscaled by `s`
// (cell centre c lands on the centre of its s x s block: c*s + (s-1)/2).
cv::Point fixed(const Point2& p, int s) {
  const double x = p.x * s + (s - 1) * 0.5;
  const double y = p.y * s + (s - 1) * 0.5;
  return {static_cast<int>(std::lround(x * kOne)), static_cast<int>(std::lround(y * kOne))};
}

bool finite(const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

const cv::Vec3b kGreyFree(255, 255, 255), kGreyUnknown(190, 190, 190), kGreyOccupied(0, 0, 0);
const cv::Scalar kWallBlue(255, 0, 0), kDoorCyan(255, 255, 0);

}  // namespace

cv::Mat1w render_labels(const WorldResult& w, int rows, int cols) {
  validate_world(w, false);
  cv::Mat1w labels(rows, cols, static_cast<std::uint16_t>(0));
  for (const auto& u : w.units) {
    if (!std::all_of(u.corners.begin(), u.corners.end(), finite)) continue;
    cv::Point pts[4];
    for (int i = 0; i < 4; ++i) pts[i] = fixed(u.corners[static_cast<std::size_t>(i)], 1);
    cv::fillConvexPoly(labels, pts, 4, cv::Scalar(u.id), cv::LINE_8, kShift);
  }
  return labels;
}

int overlay_scale(int rows, int cols) {
  const int longest = std::max(rows, cols);
  if (longest <= 0) return 1;
  return std::clamp(1200 / longest, 1, 32);
}

namespace {

cv::Scalar bgr(Rgb c) { return cv::Scalar(c.b, c.g, c.r); }

cv::Point centre_px(const Point2& c, int s) {
  return {static_cast<int>(std::lround(c.x * s + (s - 1) * 0.5)), static_cast<int>(std::lround(c.y * s + (s - 1) * 0.5))};
}

// Text centred on `at`, on a white halo.
void label(cv::Mat3b& img, const std::string& text, cv::Point at, double font, int thick, cv::Scalar colour) {
  int base_line = 0;
  const cv::Size ts = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font, thick, &base_line);
  const cv::Point org(at.x - ts.width / 2, at.y + ts.height / 2);
  cv::putText(img, text, org, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(255, 255, 255), thick + 3, cv::LINE_AA);
  cv::putText(img, text, org, cv::FONT_HERSHEY_SIMPLEX, font, colour, thick, cv::LINE_AA);
}

// The legend: a white band below the map with one swatch, letter and name per type of the run
// (none without types), so it covers no part of the map.
cv::Mat3b with_legend(const cv::Mat3b& img, const WorldResult& w, double font, int thick) {
  if (w.types.empty()) return img;
  int base_line = 0;
  const int text_h = cv::getTextSize("Ag", cv::FONT_HERSHEY_SIMPLEX, font, thick, &base_line).height;
  const int pad = text_h, swatch = text_h * 3 / 2;
  cv::Mat3b out(img.rows + swatch + 2 * pad, img.cols, cv::Vec3b(255, 255, 255));
  img.copyTo(out(cv::Rect(0, 0, img.cols, img.rows)));
  int x = pad;
  const int y = img.rows + pad;
  for (const auto& t : w.types) {
    const std::string text = type_letter(w.types, t) + " " + t;
    const cv::Rect sw(x, y, swatch, swatch);
    cv::rectangle(out, sw, bgr(type_colour(w.types, t)), cv::FILLED);
    cv::rectangle(out, sw, cv::Scalar(0, 0, 0), 1);
    cv::putText(out, text, {x + swatch + pad / 2, y + swatch - (swatch - text_h) / 2}, cv::FONT_HERSHEY_SIMPLEX, font,
                cv::Scalar(0, 0, 0), thick, cv::LINE_AA);
    x += swatch + pad / 2 + cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font, thick, &base_line).width + 2 * pad;
  }
  return out;
}

}  // namespace

cv::Mat3b render_overlay(const ClassGrid& grid, const WorldResult& w) {
  validate_world(w, false);
  if (grid.empty()) throw std::invalid_argument("overlay: empty map");
  const int s = overlay_scale(grid.rows, grid.cols);
  cv::Mat3b base(grid.rows, grid.cols);
  for (int r = 0; r < grid.rows; ++r) {
    for (int c = 0; c < grid.cols; ++c) {
      switch (static_cast<Cell>(grid(r, c))) {
        case Cell::Free: base(r, c) = kGreyFree; break;
        case Cell::Unknown: base(r, c) = kGreyUnknown; break;
        default: base(r, c) = kGreyOccupied; break;
      }
    }
  }
  cv::Mat3b img;
  cv::resize(base, img, cv::Size(), s, s, cv::INTER_NEAREST);
  const int longest = std::max(img.rows, img.cols);
  const int wall_px = std::max(2, longest / 400);
  const int door_px = wall_px + std::max(1, wall_px / 2);
  const auto drawable = [](const UnitResult& u) { return std::all_of(u.corners.begin(), u.corners.end(), finite); };
  // Units filled with their type's colour (translucent, so the map shows through), walls blue.
  cv::Mat3b fill = img.clone();
  for (const auto& u : w.units) {
    if (!drawable(u)) continue;
    std::vector<cv::Point> pts;
    for (const auto& c : u.corners) pts.push_back(fixed(c, s));
    cv::fillConvexPoly(fill, pts, bgr(type_colour(w.types, u.type)), cv::LINE_8, kShift);
  }
  cv::addWeighted(fill, 0.45, img, 0.55, 0.0, img);
  for (const auto& u : w.units) {
    if (!drawable(u)) continue;
    std::vector<cv::Point> pts;
    for (const auto& c : u.corners) pts.push_back(fixed(c, s));
    cv::polylines(img, pts, true, kWallBlue, wall_px, cv::LINE_8, kShift);
  }
  for (const auto& d : w.doors) {
    if (!finite(d.segment[0]) || !finite(d.segment[1])) continue;
    cv::line(img, fixed(d.segment[0], s), fixed(d.segment[1], s), kDoorCyan, door_px, cv::LINE_8, kShift);
  }
  // Topology (Fig. 3.32-d): centre - door - centre for every door between two units.
  std::map<int, Point2> centre;
  for (const auto& u : w.units)
    if (drawable(u)) centre[u.id] = unit_centre(u);
  const cv::Scalar kTopology(40, 40, 200);
  const int topo_px = std::max(1, wall_px / 2);
  for (const auto& d : w.doors) {
    if (!finite(d.segment[0]) || !finite(d.segment[1])) continue;
    const Point2 mid{(d.segment[0].x + d.segment[1].x) / 2.0, (d.segment[0].y + d.segment[1].y) / 2.0};
    for (const int id : {d.unit_a, d.unit_b}) {
      if (const auto it = centre.find(id); it != centre.end())
        cv::line(img, fixed(it->second, s), fixed(mid, s), kTopology, topo_px, cv::LINE_AA, kShift);
    }
    cv::circle(img, fixed(mid, s), (door_px + 1) << kShift, kTopology, cv::FILLED, cv::LINE_AA, kShift);
  }
  // The --path route, thick magenta.
  if (w.route.size() >= 2 && std::all_of(w.route.begin(), w.route.end(), finite)) {
    std::vector<cv::Point> pts;
    for (const auto& p : w.route) pts.push_back(fixed(p, s));
    cv::polylines(img, pts, false, cv::Scalar(200, 0, 200), door_px + 1, cv::LINE_AA, kShift);
    cv::circle(img, pts.front(), (2 * door_px) << kShift, cv::Scalar(0, 160, 0), cv::FILLED, cv::LINE_AA, kShift);
    cv::circle(img, pts.back(), (2 * door_px) << kShift, cv::Scalar(0, 0, 220), cv::FILLED, cv::LINE_AA, kShift);
  }
  // Type letter and id at the centres (R12), sized to the image.
  const double font = std::max(0.5, longest / 1000.0);
  const int thick = std::max(2, static_cast<int>(std::lround(font * 2.0)));
  // Labels whose boxes would overlap move apart (label_placement.h).
  std::vector<std::string> texts;
  std::vector<cv::Point> wanted;
  std::vector<cv::Size> sizes;
  for (const auto& u : w.units) {
    if (!drawable(u)) continue;
    texts.push_back(type_letter(w.types, u.type) + std::to_string(u.id));
    wanted.push_back(centre_px(unit_centre(u), s));
    int base_line = 0;
    sizes.push_back(cv::getTextSize(texts.back(), cv::FONT_HERSHEY_SIMPLEX, font, thick + 3, &base_line));
  }
  const std::vector<cv::Point> at = place_labels(wanted, sizes, std::max(1, thick / 2));
  for (std::size_t i = 0; i < texts.size(); ++i) label(img, texts[i], at[i], font, thick, cv::Scalar(120, 40, 0));
  return with_legend(img, w, font, std::max(1, thick / 2));
}

std::vector<unsigned char> encode_png(const cv::Mat& image, const std::string& what) {
  std::vector<unsigned char> buf;
  const std::vector<int> params = {cv::IMWRITE_PNG_COMPRESSION, 6};
  if (!cv::imencode(".png", image, buf, params)) {
    throw std::runtime_error("cannot encode " + what + " as PNG");
  }
  return buf;
}

void write_labels_png(const std::filesystem::path& path, const WorldResult& w, int rows, int cols) {
  runtime::io::write_file_atomic(path, encode_png(render_labels(w, rows, cols), path.string()));
}

void write_overlay_png(const std::filesystem::path& path, const ClassGrid& grid,
                       const WorldResult& w) {
  runtime::io::write_file_atomic(path, encode_png(render_overlay(grid, w), path.string()));
}

}  // namespace ksmc::stdlib::indoor::io
