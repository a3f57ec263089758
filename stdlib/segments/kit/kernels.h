// The segment kernels: BIRTH/DEATH, SPLIT/MERGE and JITTER (its own reverse), named as in
// the domain file. Each reports log Q(M'|M) for itself and log Q(M|M') for its reverse,
// the latter computed from the tentative state with the reverse kernel's own weighting
// (stdlib/segments/proposals.h).
#pragma once

#include <string>

#include "runtime/mcmc/model.h"
#include "stdlib/segments/kit/segments_model.h"

namespace ksmc::stdlib::segments::kit {

class SegmentKernel final : public runtime::mcmc::NamedKernel<SegmentsModel> {
 public:
  SegmentKernel(std::string name, std::string reverse, KernelKind kind)
      : NamedKernel(std::move(name), std::move(reverse)), kind_(kind) {}
  KernelKind kind() const { return kind_; }

 protected:
  runtime::mcmc::Proposal propose_typed(SegmentsModel& model, runtime::mcmc::Rng& rng) const override;

 private:
  KernelKind kind_;
};

// The kernels' moves, usable on their own (tests).
runtime::mcmc::Proposal propose_birth(SegmentsModel& m, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_death(SegmentsModel& m, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_split(SegmentsModel& m, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_merge(SegmentsModel& m, runtime::mcmc::Rng& rng);
runtime::mcmc::Proposal propose_jitter(SegmentsModel& m, runtime::mcmc::Rng& rng);

}  // namespace ksmc::stdlib::segments::kit
