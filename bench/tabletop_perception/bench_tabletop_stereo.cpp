// bench_tabletop_stereo [runs]: seconds per frame of the stereo front end (seed Alg. 2) on
// synthesised 640x480 stereo pairs of 5 and 10 textured boxes (synth_stereo.h grid_boxes,
// 3 scenes each). Per scene the median of `runs` (default 5) timings; the table gives the
// median over the scenes. "stereo" = SIFT on both images + epipolar matching +
// triangulation; "total" (wall; "cpu total": process CPU time) = the whole scene_from_images (stereo + database matching + pose
// hypotheses + refinement); "files" adds reading the PNGs, stereo.yaml and the model.yml
// database. Also: boxes found, and the median / max centre and rotation errors of those found.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "stdlib/tabletop/perception/stereo/scene_from_stereo.h"
#include "tools/stereo_synth/synth_stereo.h"

namespace st = ksmc::stdlib::tabletop::perception::stereo;
namespace sy = ksmc::tools::stereo_synth;
namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Median wall seconds of `runs` calls; `cpu` gets the median process CPU seconds.
double seconds(const std::function<void()>& op, int runs, double* cpu = nullptr) {
  std::vector<double> t, c;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    op();
    c.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (cpu) *cpu = median(c);
  return median(t);
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  // One folder per process: two runs at once must not share it.
  const fs::path dir = fs::temp_directory_path() / fmt::format("ksmc_bench_stereo_{}", ::getpid());
  fmt::print("bench_tabletop_stereo: median of {} runs per scene, median over 3 scenes\n", runs);
  fmt::print("{:>5} {:>8} {:>7} {:>9} {:>9} {:>9} {:>9} {:>14} {:>14}\n", "boxes", "points", "found", "s stereo",
             "s total", "cpu total", "s files", "centre mm", "angle deg");
  for (int n : {5, 10}) {
    std::vector<double> stereo, total, cpu, files, points, found, centre, angle;
    for (std::uint64_t s = 0; s < 3; ++s) {
      const std::uint64_t seed = 100 + 10 * static_cast<std::uint64_t>(n) + s;
      sy::Rig rig;
      rig.table_from_left = sy::look_at_table(0.75, 0.85, 0.15);
      const auto boxes = sy::grid_boxes(n, seed);
      const auto pair = sy::render_pair(rig, boxes, seed);
      const st::StereoCalib calib = sy::rig_calib(rig);
      fs::remove_all(dir);
      fs::create_directories(dir);
      for (const auto& b : boxes) sy::write_object_folder(dir / "db", b);
      for (const auto& b : boxes) {
        const auto m = st::build_model(dir / "db" / b.name);
        st::save_model(dir / "db" / b.name / "model.yml", m);
      }
      cv::imwrite((dir / "left.png").string(), pair.left);
      cv::imwrite((dir / "right.png").string(), pair.right);
      st::save_calib(dir / "stereo.yaml", calib);
      const auto db = st::load_database(dir / "db");
      st::StereoScene result;
      stereo.push_back(seconds([&] { result.points = st::stereo_points(pair.left, pair.right, calib); }, runs));
      double c = 0.0;
      total.push_back(
          seconds([&] { result = st::scene_from_images(pair.left, pair.right, "l", "r", calib, db); }, runs, &c));
      cpu.push_back(c);
      files.push_back(seconds(
          [&] { result = st::scene_from_stereo(dir / "left.png", dir / "right.png", dir / "stereo.yaml", dir / "db"); },
          runs));
      points.push_back(static_cast<double>(result.points.point.size()));
      found.push_back(static_cast<double>(result.scene.objects.size()));
      for (std::size_t i = 0; i < result.scene.objects.size(); ++i) {
        const auto& o = result.scene.objects[i];
        const auto& t = boxes[static_cast<std::size_t>(result.detections[i].object)];
        centre.push_back(1000.0 * (o.pose.t - t.pose.t).norm());
        angle.push_back(o.pose.q.angularDistance(t.pose.q) * 180.0 / std::numbers::pi);
      }
    }
    const double cmax = centre.empty() ? 0.0 : *std::max_element(centre.begin(), centre.end());
    const double amax = angle.empty() ? 0.0 : *std::max_element(angle.begin(), angle.end());
    fmt::print("{:>5} {:>8.0f} {:>4.0f}/{:<2} {:>9.3f} {:>9.3f} {:>9.3f} {:>9.3f} {:>6.2f} / {:<5.2f} {:>6.2f} / {:<5.2f}\n",
               n, median(points), median(found), n, median(stereo), median(total), median(cpu), median(files), median(centre), cmax,
               median(angle), amax);
  }
  fs::remove_all(dir);
  return 0;
}
