// Moves per second of the indoor sampler (propose + incremental evaluate + accept/reject) on
// lab_b.png (1237x672, the map size of the seed), or on a synthetic map of that size when the
// shared data is absent. Candidates come from a simple projection-profile stand-in for the WBU
// detector (rectangles between strong wall rows/columns). Prints a table with the median of
// five runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/dev_sampler.h"

using namespace ksmc::stdlib::indoor;

namespace {

ClassGrid load_or_synthesise(std::string& source) {
  const std::filesystem::path p =
      std::filesystem::path(KSMC_SHARED_DIR) / "data/maps/bormann_ipa/test_maps/lab_b.png";
  cv::Mat img;
  const bool present = std::filesystem::exists(p);
  if (present) img = cv::imread(p.string(), cv::IMREAD_GRAYSCALE);
  if (present && img.empty()) std::fprintf(stderr, "%s: cannot be decoded as an image\n", p.string().c_str());
  ClassGrid g;
  if (!img.empty()) {
    source = p.filename().string();
    g.create(img.rows, img.cols);
    for (int r = 0; r < img.rows; ++r)
      for (int c = 0; c < img.cols; ++c) {
        const int v = img.at<std::uint8_t>(r, c);
        // >= 250 free (the benchmark's threshold); dark = occupied; grey = unknown.
        g(r, c) = static_cast<std::uint8_t>(v >= 250 ? Cell::Free : v < 100 ? Cell::Occupied : Cell::Unknown);
      }
    return g;
  }
  source = present ? "synthetic 1237x672 (lab_b.png unreadable)" : "synthetic 1237x672 (lab_b.png not found)";
  g.create(672, 1237);
  g.setTo(static_cast<int>(Cell::Unknown));
  for (int y = 40; y + 150 < 672; y += 150)
    for (int x = 40; x + 180 < 1237; x += 180) {
      cv::rectangle(g, {x, y}, {x + 180, y + 150}, static_cast<int>(Cell::Free), cv::FILLED);
      cv::rectangle(g, {x, y}, {x + 180, y + 150}, static_cast<int>(Cell::Occupied), 3);
      cv::rectangle(g, {x + 80, y - 4}, {x + 100, y + 4}, static_cast<int>(Cell::Free), cv::FILLED);
    }
  return g;
}

// Strong wall rows (axis 0) or columns (axis 1): local maxima of the occupied-cell profile.
std::vector<double> wall_lines(const ClassGrid& g, int axis, std::size_t keep) {
  const int n = axis == 0 ? g.rows : g.cols;
  std::vector<int> prof(static_cast<std::size_t>(n), 0);
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c)
      if (g(r, c) == static_cast<std::uint8_t>(Cell::Occupied)) ++prof[static_cast<std::size_t>(axis == 0 ? r : c)];
  std::vector<std::pair<int, int>> peaks;
  for (int i = 0; i < n; ++i) {
    const int v = prof[static_cast<std::size_t>(i)];
    bool best = v >= 20;
    for (int d = -6; d <= 6 && best; ++d) {
      const int j = i + d;
      if (d != 0 && j >= 0 && j < n &&
          (prof[static_cast<std::size_t>(j)] > v || (prof[static_cast<std::size_t>(j)] == v && j < i)))
        best = false;
    }
    if (best) peaks.push_back({v, i});
  }
  std::sort(peaks.rbegin(), peaks.rend());
  if (peaks.size() > keep) peaks.resize(keep);
  std::vector<double> out;
  for (auto& p : peaks) out.push_back(p.second);
  std::sort(out.begin(), out.end());
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const long long iters = argc > 1 ? std::stoll(argv[1]) : 20000;
  std::string source;
  const ClassGrid map = load_or_synthesise(source);
  MapEvidence ev(map, 1);
  const auto xs = wall_lines(map, 1, 40), ys = wall_lines(map, 0, 30);
  std::vector<CandidateUnit> cands;
  for (std::size_t a = 0; a < xs.size(); ++a)
    for (std::size_t b = a + 1; b < std::min(xs.size(), a + 4); ++b)
      for (std::size_t c = 0; c < ys.size(); ++c)
        for (std::size_t d = c + 1; d < std::min(ys.size(), c + 4); ++d) {
          const OrientedRect r{0.5 * (xs[a] + xs[b]), 0.5 * (ys[c] + ys[d]), xs[b] - xs[a], ys[d] - ys[c], 0.0};
          const auto w = ev.wall_weights(r);
          const double wr = *std::min_element(w.begin(), w.end());
          if (wr > 0.05) cands.push_back({r, wr});
        }
  std::vector<CandidateLine> lines;
  for (double x : xs) lines.push_back({{x, 0.0}, {x, static_cast<double>(map.rows)}, 0.0});
  for (double y : ys) lines.push_back({{0.0, y}, {static_cast<double>(map.cols), y}, 0.0});
  KernelSources src;
  src.units = [&](const World&) { return std::span<const CandidateUnit>(cands); };
  src.split_lines = [&](const World&, const Unit& u) {
    std::vector<CandidateLine> out;
    const Box b = own_box(u.rect);
    for (const auto& l : lines) {
      const bool vertical = l.a.x == l.b.x;
      if (vertical ? (l.a.x > b.x0 && l.a.x < b.x1) : (l.a.y > b.y0 && l.a.y < b.y1))
        out.push_back({vertical ? Point2{l.a.x, b.y0 - 1} : Point2{b.x0 - 1, l.a.y},
                       vertical ? Point2{l.a.x, b.y1 + 1} : Point2{b.x1 + 1, l.a.y}, 0.0});
    }
    return out;
  };
  KernelParams kp;
  kp.min_size = 6.0;
  KernelSet ks(ev, src, kp);
  ScoreParams sp;
  sp.raster.wall_thickness = 1.5;

  std::printf("bench_indoor_moves: map %s (%dx%d), %zu unit candidates, %zu split lines, %lld iterations/run\n",
              source.c_str(), map.cols, map.rows, cands.size(), lines.size(), iters);
  std::printf("%4s %12s %12s %10s %8s %8s\n", "run", "seconds", "moves/s", "accepted", "units", "K(W,M)");
  std::vector<double> rates;
  for (int run = 0; run < 5; ++run) {
    ScoredWorld sw(map, sp);
    DevSampler mh(sw, ks, schedule_table_3_2(), 1000 + static_cast<std::uint64_t>(run));
    const auto t0 = std::chrono::steady_clock::now();
    long long acc = 0;
    for (long long i = 0; i < iters; ++i) acc += mh.step() ? 1 : 0;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rates.push_back(static_cast<double>(iters) / s);
    std::printf("%4d %12.3f %12.0f %10lld %8zu %8.4f\n", run, s, rates.back(), acc, sw.world().units().size(),
                sw.cell_prediction_rate());
  }
  std::printf("median moves/s: %.0f (target >= 3000 single thread)\n", median(rates));
  return 0;
}
