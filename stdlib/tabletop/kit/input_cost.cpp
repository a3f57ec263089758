#include "stdlib/tabletop/kit/input_cost.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "runtime/cli/domain_spec.h"

namespace ksmc::stdlib::tabletop::kit {

namespace {

// Chains run in rounds of --threads at once.
double chain_rounds(const runtime::cli::DomainInput& in) {
  const double threads = in.threads != 0 ? in.threads : std::max(1U, std::thread::hardware_concurrency());
  const double chains = std::max(1U, in.chains);
  return std::ceil(chains / std::min(threads, chains));
}

}  // namespace

// Measured with `/usr/bin/time -v tabletop --cloud C.ply --cloud-units mm --iterations
// 100|400|2000` on clouds of 131,536 to 1,052,288 points made of jittered copies of the
// HOPE frame's point_cloud.ply (docs/reliability.md, "Bounded work", lists the runs):
//  * peak RSS = 95 MB + 90 bytes per point;
//  * time = 1 s + 1e-10 s x points^2 (the front end's clustering: 2.5 s at 131,536 points,
//    27 s at 526,144); the sampling iterations cost nothing measurable beside it.
runtime::cli::WorkEstimate cloud_estimate(const std::string& file, std::size_t points, const runtime::cli::DomainInput&) {
  constexpr double kBaseMb = 95.0, kBytesPerPoint = 90.0;
  constexpr double kBaseSeconds = 1.0, kSecondsPerPointSquared = 1e-10;
  const double n = static_cast<double>(points);
  runtime::cli::WorkEstimate e;
  e.input = file;
  e.what = "a cloud of " + std::to_string(points) + " points";
  e.memory_mb = kBaseMb + kBytesPerPoint * n / 1e6;
  e.seconds = kBaseSeconds + kSecondsPerPointSquared * n * n;  // the front end runs once, before the chains
  return e;
}

// Measured with `/usr/bin/time -v tabletop crowdN.json --iterations 20|2000` on scenes
// of 50, 100 and 200 mutually intersecting boxes (tests/badinput/make_crowded_scene.py:
// every pair related, the worst case, so an upper bound for ordinary scenes;
// docs/reliability.md, "Bounded work", lists the runs):
//  * peak RSS = 95 MB + 0.058 MB per object + 0.00016 MB per object^2;
//  * time = 0.3 s per object + 0.000465 s per object^2 (model construction and the initial
//    Markov logic inference: 16 s at 50, 34 s at 100, 78 s at 200 objects) per chain round;
//    the iterations cost little beside it (1e-6 s per object-iteration).
runtime::cli::WorkEstimate scene_estimate(const std::string& file, std::size_t objects, const runtime::cli::DomainInput& in) {
  constexpr double kBaseMb = 95.0, kMbPerObject = 0.058, kMbPerObjectSquared = 0.00016;
  constexpr double kSecondsPerObject = 0.3, kSecondsPerObjectSquared = 0.000465, kSecondsPerObjectIteration = 1e-6;
  const double n = static_cast<double>(objects);
  runtime::cli::WorkEstimate e;
  e.input = file;
  e.what = "a scene of " + std::to_string(objects) + " objects";
  e.memory_mb = kBaseMb + kMbPerObject * n + kMbPerObjectSquared * n * n;
  e.seconds = (kSecondsPerObject * n + kSecondsPerObjectSquared * n * n +
               kSecondsPerObjectIteration * n * static_cast<double>(in.iterations)) *
              chain_rounds(in);
  return e;
}

}  // namespace ksmc::stdlib::tabletop::kit
