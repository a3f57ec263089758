// The segments model (runtime/mcmc/model.h): the segments with their incremental point
// likelihood (stdlib/segments/scene.h) and the prior of the binding's `prior` items —
// seg.complexity, mln (log Z(evidence) - log Z(no evidence atom holds)) — plus the
// conditional priors (`prior for ... where ...`), recomputed on every change. The evidence
// and the Markov logic outcome come from runtime::domain::Semantics (evidence-keyed cache).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "runtime/domain/semantics.h"
#include "runtime/mcmc/model.h"
#include "stdlib/segments/blocks.h"
#include "stdlib/segments/kit/params.h"
#include "stdlib/segments/scene.h"

namespace ksmc::stdlib::segments::kit {

// What all chains share (read-only). `binding` outlives the run (generated code keeps it).
struct SharedInput {
  const blocks::Binding* binding = nullptr;
  ModelParams params;
  std::shared_ptr<const std::vector<Vec2>> points;
  std::size_t max_lines = 200;
  double explain = DeathParams{}.explain;  // a point this close to a segment supports it (outputs)
  std::size_t candidates = 0;              // birth candidates detected (outputs)
};

struct PriorParts {
  double complexity = 0.0, mln = 0.0, semantic = 0.0;
  double total() const { return complexity + mln + semantic; }
};

using Semantics = runtime::domain::Semantics<blocks::Scene>;

class SegmentsModel final : public runtime::mcmc::Model {
 public:
  explicit SegmentsModel(std::shared_ptr<const SharedInput> shared);
  SegmentsModel(const SegmentsModel&) = delete;
  SegmentsModel& operator=(const SegmentsModel&) = delete;

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
  std::shared_ptr<const runtime::domain::Outcome> outcome() const { return outcome_; }
  const Semantics& semantics() const { return semantics_; }
  // The run-time constants' names in outputs: the constant type's name and the segment id.
  std::vector<std::string> constant_names() const;
  // Full recomputation of likelihood and prior (for checks).
  double recompute_log_posterior();

 private:
  PriorParts compute_prior(std::shared_ptr<const runtime::domain::Outcome>& outcome);

  std::shared_ptr<const SharedInput> shared_;
  Scene scene_;
  blocks::Scene view_;
  Semantics semantics_;
  PriorParts prior_, saved_prior_;
  std::shared_ptr<const runtime::domain::Outcome> outcome_, saved_outcome_;
};

}  // namespace ksmc::stdlib::segments::kit
