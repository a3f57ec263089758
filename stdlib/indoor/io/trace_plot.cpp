#include "stdlib/indoor/io/trace_plot.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/world_images.h"

namespace ksmc::stdlib::indoor::io {

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  std::vector<double> out;
  if (!std::isfinite(lo) || !std::isfinite(hi) || target_count < 1) return out;
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) return {lo};
  const double raw = (hi - lo) / target_count;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (const double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double t = first; t <= hi + step * 1e-9; t += step) out.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
  return out;
}

namespace {

constexpr int kWidth = 1000, kPanelHeight = 350;
constexpr int kLeft = 110, kRight = 30, kTop = 40, kBottom = 50;
const cv::Scalar kAxis(0, 0, 0), kGrid(225, 225, 225), kText(40, 40, 40);

std::string tick_label(double v, double step) {
  if (std::fabs(v) >= 1e6 || (std::fabs(v) > 0 && std::fabs(v) < 1e-3)) return fmt::format("{:.3g}", v);
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return fmt::format("{:.{}f}", v, decimals);
}

struct Panel {
  cv::Rect area;  // plotting area inside the panel
  double x0, x1, y0, y1;
  int px(double x) const {
    return area.x + static_cast<int>(std::lround((x - x0) / (x1 - x0) * area.width));
  }
  int py(double y) const {
    return area.y + area.height - static_cast<int>(std::lround((y - y0) / (y1 - y0) * area.height));
  }
};

void put(cv::Mat3b& img, const std::string& s, cv::Point org, double scale = 0.45) {
  cv::putText(img, s, org, cv::FONT_HERSHEY_SIMPLEX, scale, kText, 1, cv::LINE_AA);
}

void draw_axes(cv::Mat3b& img, const Panel& p, const std::string& title, const std::string& xlabel) {
  const auto xt = nice_ticks(p.x0, p.x1, 8);
  const auto yt = nice_ticks(p.y0, p.y1, 6);
  const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
  const double ys = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (double t : xt) {
    const int x = p.px(t);
    cv::line(img, {x, p.area.y}, {x, p.area.y + p.area.height}, kGrid, 1);
    cv::line(img, {x, p.area.y + p.area.height}, {x, p.area.y + p.area.height + 5}, kAxis, 1);
    const std::string s = tick_label(t, xs);
    int bl = 0;
    const cv::Size ts = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &bl);
    put(img, s, {x - ts.width / 2, p.area.y + p.area.height + 20});
  }
  for (double t : yt) {
    const int y = p.py(t);
    cv::line(img, {p.area.x, y}, {p.area.x + p.area.width, y}, kGrid, 1);
    cv::line(img, {p.area.x - 5, y}, {p.area.x, y}, kAxis, 1);
    const std::string s = tick_label(t, ys);
    int bl = 0;
    const cv::Size ts = cv::getTextSize(s, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &bl);
    put(img, s, {p.area.x - 9 - ts.width, y + ts.height / 2});
  }
  cv::rectangle(img, p.area, kAxis, 1);
  put(img, title, {p.area.x, p.area.y - 12}, 0.6);
  int bl = 0;
  const cv::Size ts = cv::getTextSize(xlabel, cv::FONT_HERSHEY_SIMPLEX, 0.5, 1, &bl);
  put(img, xlabel, {p.area.x + p.area.width / 2 - ts.width / 2, p.area.y + p.area.height + 42}, 0.5);
}

// Pads a value range so flat or single-point series still get a visible axis.
void pad_range(double& lo, double& hi) {
  if (!(hi > lo)) {
    const double d = std::max(1.0, std::fabs(lo) * 0.05);
    lo -= d;
    hi += d;
    return;
  }
  const double d = (hi - lo) * 0.05;
  lo -= d;
  hi += d;
}

void draw_series(cv::Mat3b& img, const Panel& p, const std::vector<cv::Point2d>& pts, cv::Scalar colour) {
  std::vector<cv::Point> poly;
  for (const auto& q : pts) poly.emplace_back(p.px(q.x), p.py(q.y));
  if (poly.size() == 1) {
    cv::circle(img, poly[0], 3, colour, cv::FILLED, cv::LINE_AA);
  } else if (poly.size() > 1) {
    cv::polylines(img, poly, false, colour, 2, cv::LINE_AA);
  }
}

}  // namespace

cv::Mat3b render_trace(const std::vector<TraceSample>& trace) {
  cv::Mat3b img(2 * kPanelHeight, kWidth, cv::Vec3b(255, 255, 255));
  std::vector<cv::Point2d> lp, acc;
  for (const auto& t : trace) {
    const double it = static_cast<double>(t.iteration);
    if (std::isfinite(t.log_posterior)) lp.emplace_back(it, t.log_posterior);
    if (std::isfinite(t.acceptance_rate)) acc.emplace_back(it, std::clamp(t.acceptance_rate, 0.0, 1.0));
  }
  double x0 = 0.0, x1 = 1.0;
  if (!trace.empty()) {
    x0 = static_cast<double>(trace.front().iteration);
    x1 = x0;
    for (const auto& t : trace) {
      x0 = std::min(x0, static_cast<double>(t.iteration));
      x1 = std::max(x1, static_cast<double>(t.iteration));
    }
    if (x1 == x0) x1 = x0 + 1.0;
  }
  double y0 = 0.0, y1 = 1.0;
  if (!lp.empty()) {
    y0 = y1 = lp.front().y;
    for (const auto& q : lp) y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  pad_range(y0, y1);
  const cv::Rect a0(kLeft, kTop, kWidth - kLeft - kRight, kPanelHeight - kTop - kBottom);
  const cv::Rect a1(kLeft, kPanelHeight + kTop, a0.width, a0.height);
  const Panel top{a0, x0, x1, y0, y1};
  const Panel bottom{a1, x0, x1, 0.0, 1.0};
  draw_axes(img, top, "log posterior log p(W|M)", "iteration");
  draw_axes(img, bottom, "acceptance rate", "iteration");
  draw_series(img, top, lp, cv::Scalar(180, 80, 0));
  draw_series(img, bottom, acc, cv::Scalar(0, 0, 200));
  if (trace.empty()) {
    put(img, "no trace samples", {a0.x + a0.width / 2 - 70, a0.y + a0.height / 2}, 0.6);
  }
  return img;
}

void write_trace_png(const std::filesystem::path& path, const std::vector<TraceSample>& trace) {
  runtime::io::write_file_atomic(path, encode_png(render_trace(trace), path.string()));
}

}  // namespace ksmc::stdlib::indoor::io
