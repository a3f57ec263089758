// Moves per second of the indoor sampler (propose + incremental evaluate + accept/reject) on
// lab_b.png (1237x672, the map size of the seed), or on a synthetic map of that size when the
// shared data is absent. Candidates come from a simple projection-profile stand-in for the WBU
// detector (rectangles between strong wall rows/columns). Prints a table with the median of
// five runs.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <tuple>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/detect/door.h"
#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/detect/split.h"
#include "stdlib/indoor/detect/wbu.h"
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

// Sources from stdlib/indoor/detect: WBU candidates (once), split lines per unit and door
// candidates per world (cached).
struct DetectSources {
  const ClassGrid& map;
  std::vector<CandidateUnit> units;
  std::map<std::tuple<double, double, double, double, double>, std::vector<CandidateLine>> splits;
  std::vector<double> door_key;
  std::vector<CandidateDoor> doors;
  double dominant = 0.0;

  explicit DetectSources(const ClassGrid& m) : map(m) {
    const auto wbu = detect::detect_wbu_units(map);
    units = to_unit_candidates(wbu.candidates);
    dominant = wbu.frames_deg.empty() ? 0.0 : wbu.frames_deg.front() * kPi / 180.0;
  }
  KernelSources sources() {
    KernelSources s;
    s.units = [this](const World&) { return std::span<const CandidateUnit>(units); };
    s.split_lines = [this](const World&, const Unit& u) {
      const auto key = std::make_tuple(u.rect.cx, u.rect.cy, u.rect.w, u.rect.h, u.rect.theta);
      auto it = splits.find(key);
      if (it == splits.end())
        it = splits.emplace(key, to_line_candidates(detect::detect_split_lines(map, u.rect))).first;
      return it->second;
    };
    s.doors = [this](const World& w) {
      std::vector<double> key;
      std::vector<OrientedRect> rects;
      for (const Unit& u : w.units()) {
        key.insert(key.end(), {static_cast<double>(u.id), u.rect.cx, u.rect.cy, u.rect.w, u.rect.h, u.rect.theta});
        rects.push_back(u.rect);
      }
      if (key != door_key) {
        door_key = key;
        doors = to_door_candidates(detect::detect_doors(map, rects));
      }
      return std::span<const CandidateDoor>(doors);
    };
    return s;
  }
};

int main(int argc, char** argv) {
  long long iters = 20000;
  bool use_detect = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--detect") use_detect = true;
    else if (a.find_first_not_of("0123456789") == std::string::npos) iters = std::stoll(a);
    else {
      std::fprintf(stderr, "usage: bench_indoor_moves [iterations] [--detect]\n");
      return 2;
    }
  }
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
  std::unique_ptr<DetectSources> det;
  KernelParams kp;
  kp.min_size = 6.0;
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
  if (use_detect) {
    const auto t0 = std::chrono::steady_clock::now();
    det = std::make_unique<DetectSources>(map);
    src = det->sources();
    kp.orientation.enabled = true;
    kp.orientation.dominant = det->dominant;
    std::printf("detect sources: %zu WBU candidates in %.2f s, dominant orientation %.2f deg\n", det->units.size(),
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                det->dominant * 180.0 / kPi);
  }
  KernelSet ks(ev, src, kp);
  ScoreParams sp;
  sp.raster.wall_thickness = 1.5;

  std::printf("bench_indoor_moves: map %s (%dx%d), sources %s, %lld iterations/run\n", source.c_str(), map.cols,
              map.rows,
              use_detect ? "stdlib/indoor/detect" : ("profile stand-in (" + std::to_string(cands.size()) + " units, " +
                                                     std::to_string(lines.size()) + " lines)").c_str(),
              iters);
  // Wall-clock and process CPU time: on a shared machine the CPU rate is the single-thread figure.
  std::printf("%4s %9s %9s %10s %12s %9s %6s %7s\n", "run", "wall s", "cpu s", "moves/s", "moves/cpu-s", "accepted",
              "units", "K(W,M)");
  std::vector<double> rates, cpu_rates;
  for (int run = 0; run < 5; ++run) {
    ScoredWorld sw(map, sp);
    DevSampler mh(sw, ks, schedule_table_3_2(), 1000 + static_cast<std::uint64_t>(run));
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    long long acc = 0;
    for (long long i = 0; i < iters; ++i) acc += mh.step() ? 1 : 0;
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rates.push_back(static_cast<double>(iters) / s);
    cpu_rates.push_back(static_cast<double>(iters) / cpu);
    std::printf("%4d %9.3f %9.3f %10.0f %12.0f %9lld %6zu %7.4f\n", run, s, cpu, rates.back(), cpu_rates.back(), acc,
                sw.world().units().size(), sw.cell_prediction_rate());
  }
  std::printf("median moves/s: %.0f wall-clock, %.0f per CPU second (target >= 3000 single thread)\n", median(rates),
              median(cpu_rates));
  return 0;
}
