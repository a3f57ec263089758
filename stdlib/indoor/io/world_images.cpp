#include "stdlib/indoor/io/world_images.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "runtime/io/atomic_file.h"
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
  for (const auto& u : w.units) {
    if (!std::all_of(u.corners.begin(), u.corners.end(), finite)) continue;
    std::vector<cv::Point> pts;
    for (const auto& c : u.corners) pts.push_back(fixed(c, s));
    cv::polylines(img, pts, true, kWallBlue, wall_px, cv::LINE_8, kShift);
  }
  for (const auto& d : w.doors) {
    if (!finite(d.segment[0]) || !finite(d.segment[1])) continue;
    cv::line(img, fixed(d.segment[0], s), fixed(d.segment[1], s), kDoorCyan, door_px, cv::LINE_8,
             kShift);
  }
  // Unit ids at the centres: dark blue text on a white halo, sized to the image.
  const double font = std::max(0.5, longest / 1000.0);
  const int thick = std::max(2, static_cast<int>(std::lround(font * 2.0)));
  for (const auto& u : w.units) {
    if (!std::all_of(u.corners.begin(), u.corners.end(), finite)) continue;
    Point2 c{0.0, 0.0};
    for (const auto& p : u.corners) c = {c.x + p.x / 4.0, c.y + p.y / 4.0};
    const std::string text = std::to_string(u.id);
    int base_line = 0;
    const cv::Size ts = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font, thick, &base_line);
    const cv::Point org(static_cast<int>(std::lround(c.x * s + (s - 1) * 0.5)) - ts.width / 2,
                        static_cast<int>(std::lround(c.y * s + (s - 1) * 0.5)) + ts.height / 2);
    cv::putText(img, text, org, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(255, 255, 255),
                thick + 3, cv::LINE_AA);
    cv::putText(img, text, org, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(120, 40, 0), thick,
                cv::LINE_AA);
  }
  return img;
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
