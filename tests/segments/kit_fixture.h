// Shared setup of the segments kit tests: the example domain's generated binding
// (examples/segments/segments.ksm), the bundled room cloud, and the binding's kernels by the
// move they make (not by name), each with its own parameters and birth candidates.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "runtime/mcmc/rng.h"
#include "segments_model.h"  // generated from examples/segments/segments.ksm
#include "stdlib/segments/cloud.h"
#include "stdlib/segments/kit/kernels.h"
#include "stdlib/segments/kit/segments_model.h"

namespace segments_test {

namespace seg = ksmc::stdlib::segments;
using ksmc::runtime::mcmc::Proposal;
using ksmc::runtime::mcmc::Rng;

inline const seg::blocks::Binding& binding() { return ksmc_generated::segments::binding(); }

inline std::shared_ptr<const seg::kit::SharedInput> room_input() {
  auto sh = std::make_shared<seg::kit::SharedInput>();
  sh->binding = &binding();
  sh->params = seg::kit::model_params(binding());
  sh->points = std::make_shared<const std::vector<seg::Vec2>>(
      seg::load_points(std::string(KSMC_SOURCE_DIR) + "/examples/segments/room.txt"));
  return sh;
}

// The kernel of the binding that makes `move`, its candidates detected with seed 1.
inline const seg::kit::KernelData& kernel(seg::blocks::Move move) {
  static const auto table = [] {
    std::map<seg::blocks::Move, seg::kit::KernelData> t;
    const auto points = room_input()->points;
    for (const auto& decl : binding().kernels) {
      seg::kit::KernelData d;
      d.params = seg::kit::kernel_params(decl);
      if (d.params.detects)
        d.candidates = std::make_shared<const std::vector<seg::Candidate>>(seg::detect_candidates(*points, d.params.ransac, 1));
      t.emplace(decl.move, d);
    }
    return t;
  }();
  return table.at(move);
}

inline Proposal birth(seg::kit::SegmentsModel& m, Rng& r) { return seg::kit::propose_birth(m, kernel(seg::blocks::Move::birth), r); }
inline Proposal death(seg::kit::SegmentsModel& m, Rng& r) { return seg::kit::propose_death(m, kernel(seg::blocks::Move::death), r); }
inline Proposal split(seg::kit::SegmentsModel& m, Rng& r) { return seg::kit::propose_split(m, kernel(seg::blocks::Move::split), r); }
inline Proposal merge(seg::kit::SegmentsModel& m, Rng& r) { return seg::kit::propose_merge(m, kernel(seg::blocks::Move::merge), r); }
inline Proposal jitter(seg::kit::SegmentsModel& m, Rng& r) { return seg::kit::propose_jitter(m, kernel(seg::blocks::Move::jitter), r); }

}  // namespace segments_test
