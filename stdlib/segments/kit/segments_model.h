// The segments model (runtime/mcmc/model.h): a Scene (lines + incremental point
// likelihood) and the prior  complexity + mln + semantic terms, recomputed on every change
// (O(lines^2) relation tests; Markov logic results come from the evidence-keyed cache).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "runtime/domain/config.h"
#include "runtime/mcmc/model.h"
#include "stdlib/segments/detect.h"
#include "stdlib/segments/kit/semantics.h"
#include "stdlib/segments/kit/settings.h"
#include "stdlib/segments/scene.h"

namespace ksmc::stdlib::segments::kit {

// What all chains share (read-only).
struct SharedInput {
  SegmentsSettings settings;
  std::shared_ptr<const std::vector<Vec2>> points;
  std::vector<Candidate> candidates;
  runtime::domain::MlnBinding binding;
  std::size_t max_lines = 200;
};

struct PriorParts {
  double complexity = 0.0, mln = 0.0, semantic = 0.0;
  double total() const { return complexity + mln + semantic; }
};

class SegmentsModel final : public runtime::mcmc::Model {
 public:
  explicit SegmentsModel(std::shared_ptr<const SharedInput> shared);

  double log_likelihood() const override { return scene_.log_likelihood(); }
  double log_prior() const override { return prior_.total(); }
  void accept() override;
  void reject() override;
  runtime::mcmc::Snapshot snapshot() const override;
  void restore(const runtime::mcmc::Snapshot& state) override;

  // Tentative change for a kernel (see Scene::change); `ids` (optional, one per added line)
  // keeps the ids of lines that are moved rather than created.
  std::vector<std::size_t> change(std::span<const std::size_t> remove, std::span<const Segment> add,
                                  std::span<const std::uint64_t> ids = {});

  const Scene& scene() const { return scene_; }
  const SharedInput& shared() const { return *shared_; }
  const PriorParts& prior_parts() const { return prior_; }
  std::shared_ptr<const MlnOutcome> outcome() const { return outcome_; }
  Semantics& semantics() { return semantics_; }
  // Full recomputation of likelihood and prior (for checks).
  double recompute_log_posterior();

 private:
  PriorParts compute_prior(std::shared_ptr<const MlnOutcome>& outcome);

  std::shared_ptr<const SharedInput> shared_;
  Scene scene_;
  Semantics semantics_;
  PriorParts prior_, saved_prior_;
  std::shared_ptr<const MlnOutcome> outcome_, saved_outcome_;
};

}  // namespace ksmc::stdlib::segments::kit
