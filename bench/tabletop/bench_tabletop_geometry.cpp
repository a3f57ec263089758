// bench_tabletop_geometry: time of evidence extraction (full and incremental),
// scene keypoint likelihood and one DDMCMC pose proposal (n = 20 candidates) on
// synthetic table-top scenes of 5, 10 and 20 objects. Prints the median of 7 runs;
// each run repeats the operation until at least 20 ms have passed.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "stdlib/tabletop/evidence.h"
#include "stdlib/tabletop/likelihood.h"
#include "stdlib/tabletop/pose_proposal.h"

using namespace ksmc::stdlib::tabletop;

namespace {

// Objects on a jittered grid; every third one stacked on its predecessor; 12
// keypoints each (corners + 4 surface points), observed with 0.5 px noise.
Scene make_scene(int n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  s.camera = {615, 615, 320, 240, 640, 480};
  s.table_in_camera.t = Eigen::Vector3d(0.0, 0.05, 1.1);
  s.table_in_camera.q = Eigen::Quaterniond(Eigen::AngleAxisd(2.5, Eigen::Vector3d::UnitX()));
  for (int i = 0; i < n; ++i) {
    SceneObject o;
    o.id = "o" + std::to_string(i);
    o.model = "box";
    o.size = Eigen::Vector3d(0.06 + 0.02 * u(rng), 0.08 + 0.02 * u(rng), 0.05 + 0.03 * u(rng));
    const bool stacked = i % 3 == 2;
    const SceneObject* below = stacked ? &s.objects.back() : nullptr;
    const int cell = i - i / 3;  // stacked objects share their predecessor's cell
    const double x = -0.35 + 0.14 * (cell % 6) + 0.01 * u(rng);
    const double y = -0.2 + 0.14 * (cell / 6) + 0.01 * u(rng);
    const double base = below ? below->pose.t.z() + 0.5 * below->size.z() : 0.0;
    o.pose.t = below ? Eigen::Vector3d(below->pose.t.x(), below->pose.t.y(), base + 0.5 * o.size.z())
                     : Eigen::Vector3d(x, y, 0.5 * o.size.z());
    o.pose.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * u(rng), Eigen::Vector3d::UnitZ()));
    for (int k = 0; k < 8; ++k)
      o.keypoints_model.push_back(0.5 * o.size.cwiseProduct(
          Eigen::Vector3d((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1)));
    for (int k = 0; k < 4; ++k)
      o.keypoints_model.push_back(0.5 * o.size.cwiseProduct(Eigen::Vector3d(u(rng), u(rng), 1.0)));
    const Eigen::Isometry3d cam = s.table_in_camera.compose(o.pose).isometry();
    for (const auto& m : o.keypoints_model) {
      Eigen::Vector2d uv = project(s.camera, cam * m).value_or(Eigen::Vector2d::Zero());
      uv += Eigen::Vector2d(0.5 * u(rng), 0.5 * u(rng));
      o.keypoints_image.push_back(uv);
    }
    s.objects.push_back(o);
  }
  return s;
}

// Median over `runs` of the mean time per call [µs].
double median_us(const std::function<void()>& op, int runs = 7) {
  using clock = std::chrono::steady_clock;
  std::vector<double> per_call;
  for (int r = 0; r < runs; ++r) {
    long calls = 0;
    const auto start = clock::now();
    auto now = start;
    do {
      op();
      ++calls;
      now = clock::now();
    } while (now - start < std::chrono::milliseconds(20));
    per_call.push_back(std::chrono::duration<double, std::micro>(now - start).count() / static_cast<double>(calls));
  }
  std::sort(per_call.begin(), per_call.end());
  return per_call[per_call.size() / 2];
}

volatile double g_sink = 0.0;  // keeps results observable

}  // namespace

int main() {
  std::printf("bench_tabletop_geometry: median of 7 runs, microseconds per call\n");
  std::printf("%8s %10s %14s %16s %14s %18s %14s\n", "objects", "atoms", "extract_full", "update_one_obj",
              "likelihood", "proposal_n20", "iteration");
  for (int n : {5, 10, 20}) {
    Scene scene = make_scene(n, 1000 + static_cast<std::uint64_t>(n));
    Evidence ev = extract_evidence(scene);
    std::size_t atoms = 0;  // true relations (table, stable, hover; ordered pairs)
    for (std::size_t a = 0; a < ev.size(); ++a) {
      atoms += static_cast<std::size_t>(ev.is_table[a] + ev.stable[a] + ev.hover[a]);
      for (std::size_t b = 0; b < ev.size(); ++b)
        if (a != b) atoms += static_cast<std::size_t>(ev.contact[a][b] + ev.intersect[a][b] + ev.higher[a][b]);
    }
    const double t_full = median_us([&] { g_sink = g_sink + static_cast<double>(extract_evidence(scene).stable[1]); });
    std::size_t k = 0;
    const double t_update = median_us([&] {
      update_evidence(ev, scene, k, {});
      k = (k + 1) % scene.objects.size();
    });
    const double t_lik = median_us([&] { g_sink = g_sink + scene_log_likelihood(scene); });
    std::mt19937_64 rng(7);
    const PoseProposalParams params;  // n = 20
    std::size_t j = 0;
    const double t_prop = median_us([&] {
      const PoseProposal p = propose_pose(scene, j, params, {}, rng);
      g_sink = g_sink + p.log_q_forward;
      j = (j + 1) % scene.objects.size();
    });
    // One KSMCMC iteration's geometry+data work: propose, re-extract the moved object, scene likelihood.
    std::mt19937_64 rng2(8);
    std::size_t m = 0;
    const double t_iter = median_us([&] {
      const PoseProposal p = propose_pose(scene, m, params, {}, rng2);
      const Pose old = scene.objects[m].pose;
      scene.objects[m].pose = p.pose;
      update_evidence(ev, scene, m, {});
      g_sink = g_sink + scene_log_likelihood(scene);
      scene.objects[m].pose = old;  // reject: keep the scene fixed across runs
      update_evidence(ev, scene, m, {});
      m = (m + 1) % scene.objects.size();
    });
    std::printf("%8d %10zu %14.1f %16.1f %14.2f %18.1f %14.1f\n", n, atoms, t_full, t_update, t_lik, t_prop, t_iter);
  }
  return 0;
}
