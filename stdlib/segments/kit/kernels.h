// The segment kernels, one per direction of a kernel declaration of the binding, making the
// declaration's move (blocks::Move: birth, death, split, merge, jitter) with the parameters
// of its proposal sources. Each reports log Q(M'|M) for itself and log Q(M|M') for its
// reverse, the latter computed from the tentative state with the reverse move's own
// weighting (stdlib/segments/proposals.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/mcmc/model.h"
#include "stdlib/segments/detect.h"
#include "stdlib/segments/kit/params.h"
#include "stdlib/segments/kit/segments_model.h"

namespace ksmc::stdlib::segments::kit {

// What one kernel direction needs: its parameters and, for birth / death, the candidates
// its detect.ransac source found (shared by both directions).
struct KernelData {
  KernelParams params;
  std::shared_ptr<const std::vector<Candidate>> candidates = std::make_shared<const std::vector<Candidate>>();
};

class SegmentKernel final : public runtime::mcmc::NamedKernel<SegmentsModel> {
 public:
  SegmentKernel(std::string name, std::string reverse, KernelData data)
      : NamedKernel(std::move(name), std::move(reverse)), data_(std::move(data)) {}
  blocks::Move move() const { return data_.params.move; }

 protected:
  runtime::mcmc::Proposal propose_typed(SegmentsModel& model, runtime::mcmc::Rng& rng) const override;

 private:
  KernelData data_;
};

// The moves, usable on their own (tests).
runtime::mcmc::Proposal propose_birth(SegmentsModel& m, const KernelData& k, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_death(SegmentsModel& m, const KernelData& k, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_split(SegmentsModel& m, const KernelData& k, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_merge(SegmentsModel& m, const KernelData& k, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_jitter(SegmentsModel& m, const KernelData& k, runtime::mcmc::Rng& rng);

}  // namespace ksmc::stdlib::segments::kit
