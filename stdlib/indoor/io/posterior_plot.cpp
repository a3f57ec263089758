#include "stdlib/indoor/io/posterior_plot.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/io/world_images.h"

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr int kShift = 4;

cv::Point fixed(const Point2& p, int s) {
  return {static_cast<int>(std::lround((p.x * s + (s - 1) * 0.5) * (1 << kShift))),
          static_cast<int>(std::lround((p.y * s + (s - 1) * 0.5) * (1 << kShift)))};
}

void outline(cv::Mat& img, const std::array<Point2, 4>& q, int s, const cv::Scalar& colour, int px) {
  std::vector<cv::Point> pts;
  for (const auto& p : q) pts.push_back(fixed(p, s));
  cv::polylines(img, pts, true, colour, px, cv::LINE_8, kShift);
}

}  // namespace

cv::Mat3b render_posterior(const ClassGrid& grid, const WorldResult& w) {
  if (w.posterior.empty()) throw std::invalid_argument("posterior: no stored samples");
  if (grid.empty()) throw std::invalid_argument("posterior: empty map");
  const int s = overlay_scale(grid.rows, grid.cols);
  cv::Mat3b base(grid.rows, grid.cols);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const auto cell = static_cast<Cell>(grid(r, c));
      base(r, c) = cell == Cell::Free ? cv::Vec3b(255, 255, 255) : cell == Cell::Unknown ? cv::Vec3b(215, 215, 215) : cv::Vec3b(150, 150, 150);
    }
  cv::Mat3b img;
  cv::resize(base, img, cv::Size(), s, s, cv::INTER_NEAREST);
  const std::size_t first = w.posterior.size() > kPosteriorMaxDrawn ? w.posterior.size() - kPosteriorMaxDrawn : 0;
  const std::size_t drawn = w.posterior.size() - first;
  // Per pixel: the number of drawn samples with a unit outline there.
  // Per sample, the outlines go into `mask`; each unit's bounding box is then added to the count
  // and cleared, so a pixel two units of one sample share counts once and the whole image is
  // never touched per sample (large maps, many samples).
  cv::Mat1f count(img.rows, img.cols, 0.0f);
  cv::Mat1b mask(img.rows, img.cols, static_cast<std::uint8_t>(0));
  const cv::Rect whole(0, 0, img.cols, img.rows);
  for (std::size_t i = first; i < w.posterior.size(); ++i) {
    std::vector<cv::Rect> boxes;
    for (const auto& q : w.posterior[i].units) {
      if (!finite_quad(q)) continue;
      outline(mask, q, s, cv::Scalar(1), 1);
      double x0 = q[0].x, x1 = q[0].x, y0 = q[0].y, y1 = q[0].y;
      for (const auto& p : q) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
      const cv::Point a(static_cast<int>(std::floor(x0 * s)) - 1, static_cast<int>(std::floor(y0 * s)) - 1);
      const cv::Point b(static_cast<int>(std::ceil((x1 + 1) * s)) + 1, static_cast<int>(std::ceil((y1 + 1) * s)) + 1);
      boxes.push_back(cv::Rect(a, b) & whole);
    }
    for (const auto& box : boxes) {
      if (box.empty()) continue;
      cv::Mat1f c = count(box);
      cv::add(c, cv::Scalar(1.0), c, mask(box));
      mask(box).setTo(0);
    }
  }
  for (int r = 0; r < img.rows; ++r)
    for (int c = 0; c < img.cols; ++c) {
      const float n = count(r, c);
      if (n <= 0.0f) continue;
      // At least a faint line for one sample; dark red where every sample agrees.
      const double share = 0.25 + 0.75 * static_cast<double>(n) / static_cast<double>(drawn);
      const cv::Vec3b target(0, 0, 190);
      cv::Vec3b& px = img(r, c);
      for (int k = 0; k < 3; ++k) px[k] = cv::saturate_cast<std::uint8_t>(px[k] + (target[k] - px[k]) * share);
    }
  // Caption band.
  const double font = std::max(0.55, img.cols / 1800.0);  // legible on large maps too
  const int thick = std::max(1, static_cast<int>(std::lround(font)));
  const int band = static_cast<int>(std::lround(36 * font / 0.55));
  cv::Mat3b out(img.rows + band, img.cols, cv::Vec3b(255, 255, 255));
  img.copyTo(out(cv::Rect(0, 0, img.cols, img.rows)));
  const std::string caption = "last " + std::to_string(drawn) + " stored samples (iterations " +
                              std::to_string(w.posterior[first].iteration) + "-" + std::to_string(w.posterior.back().iteration) +
                              "): darker = more samples agree";
  cv::putText(out, caption, {8, img.rows + band * 2 / 3}, cv::FONT_HERSHEY_SIMPLEX, font, cv::Scalar(0, 0, 0), thick, cv::LINE_AA);
  return out;
}

void write_posterior_png(const std::filesystem::path& path, const ClassGrid& grid, const WorldResult& w) {
  runtime::io::write_file_atomic(path, encode_png(render_posterior(grid, w), path.string()));
}

}  // namespace ksmc::stdlib::indoor::io
