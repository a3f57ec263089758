// bench_tabletop_perception [runs]: seconds per frame of the point-cloud front end on
// simulated depth clouds (640x480, every 2nd pixel, 1 mm depth noise at 1 m) of generated
// scenes with 5 and 10 boxes (singles and stacks families, 3 scenes each). Per scene the
// median of `runs` (default 7) timings; the table gives the median over the scenes.
// "in memory" is scene_from_points; "PLY" adds reading the cloud from an ASCII PLY file;
// "likelihood" is one full cloud-likelihood evaluation as the kit scores it (the sensor known),
// "all faces" the same measured to every face (before stop 39), and one single-object update;
// "upright" is scene_from_points with the tilted-box search off (ClusterBoxOptions::tilted),
// "no joins" the same with the clusters joined by the tolerance alone (no grazing-top rows,
// ClusterOptions::slant_factor = 0, and no shadow merge), each timed right after "mem" so
// that all see the same load.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "stdlib/tabletop/cloud_likelihood.h"
#include "tools/perception_sim/sim_cloud.h"

namespace pc = ksmc::stdlib::tabletop::perception;
namespace ps = ksmc::tools::perception_sim;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double seconds(const std::function<void()>& op, int runs) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    op();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return median(t);
}

int run(int runs) {
  // One folder per process: two runs at once (base and change side by side) must not share it.
  const auto dir = std::filesystem::temp_directory_path() / fmt::format("ksmc_bench_perception_{}", ::getpid());
  std::filesystem::create_directories(dir);
  fmt::print("bench_tabletop_perception: median of {} runs per scene, median over 3 scenes\n", runs);
  fmt::print("{:<8} {:>5} {:>8} {:>7} {:>14} {:>10} {:>10} {:>10} {:>14} {:>14} {:>14}\n", "family", "boxes",
             "points", "found", "s/frame (mem)", "upright", "no joins", "s/frame PLY", "us likelihood", "us all faces",
             "us update");
  for (int n : {5, 10}) {
    for (const std::string name : {"singles", "stacks"}) {
      ps::SimFamily fam;
      for (auto& f : ps::sim_families(n, n))
        if (f.name == name) fam = f;
      std::vector<double> mem, upright, no_joins, ply, lik, lik_all, upd, points, found;
      for (std::uint64_t s = 0; s < 3; ++s) {
        const ps::SimFrame f = ps::simulate_frame(ksmc::tools::tabletop_sim::scene_seed(42 + static_cast<std::uint64_t>(n), s), fam);
        pc::CloudOptions opt;
        opt.camera = ps::scene_camera(f.scene.camera);
        pc::CloudScene cs;
        mem.push_back(seconds([&] { cs = pc::scene_from_points(f.cloud, "bench", opt); }, runs));
        pc::CloudOptions upright_only = opt;
        upright_only.fit.tilted = false;
        upright.push_back(seconds([&] { (void)pc::scene_from_points(f.cloud, "bench", upright_only); }, runs));
        pc::CloudOptions unjoined = opt;
        unjoined.clusters.slant_factor = 0.0;
        unjoined.shadow.enabled = false;
        no_joins.push_back(seconds([&] { (void)pc::scene_from_points(f.cloud, "bench", unjoined); }, runs));
        const auto file = dir / "frame.ply";
        pc::save_ply(file, f.cloud);
        ply.push_back(seconds([&] { cs = pc::scene_from_cloud(file, opt); }, runs));
        std::vector<ksmc::stdlib::tabletop::Obb> boxes;
        for (const auto& o : cs.scene.objects) boxes.push_back(o.obb());
        // As the kit scores them: the sensor known (no point measured to the face a box stands
        // on); "all faces" is the same without it.
        ksmc::stdlib::tabletop::CloudLikelihoodParams seen, all_faces;
        seen.sensor = cs.sensor_in_table;
        ksmc::stdlib::tabletop::CloudLikelihood cl(cs.object_points, boxes, seen);
        volatile double sink = 0.0;
        lik.push_back(1e6 * seconds([&] { sink = sink + ksmc::stdlib::tabletop::CloudLikelihood(cs.object_points, boxes, seen).total(); }, runs));
        lik_all.push_back(1e6 * seconds([&] { sink = sink + ksmc::stdlib::tabletop::CloudLikelihood(cs.object_points, boxes, all_faces).total(); }, runs));
        auto moved = boxes[0];
        moved.center.z() += 0.001;
        upd.push_back(1e6 * seconds([&] { sink = sink + cl.update(0, moved); }, runs));
        points.push_back(static_cast<double>(f.cloud.size()));
        found.push_back(static_cast<double>(cs.scene.objects.size()));
      }
      fmt::print("{:<8} {:>5} {:>8.0f} {:>7.0f} {:>14.4f} {:>10.4f} {:>10.4f} {:>10.4f} {:>14.0f} {:>14.0f} {:>14.0f}\n",
                 name, n, median(points), median(found), median(mem), median(upright), median(no_joins), median(ply),
                 median(lik), median(lik_all), median(upd));
    }
  }
  std::filesystem::remove_all(dir);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  try {
    return run(runs);
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_tabletop_perception: {}\n", e.what());
    return 1;
  }
}
