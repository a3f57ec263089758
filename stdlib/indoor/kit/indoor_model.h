// The indoor model behind the runtime/mcmc engine: a ScoredWorld (incremental likelihood +
// weak prior), one KernelSet per source pool (each kernel draws from the proposal sources its
// declaration names, KitPlan), plus the semantic layer: every `semantic_every` proposals the
// Markov logic types of the units are refreshed (cached by evidence) and folded into that
// proposal: units whose type is a lenient type of the likelihood switch to the lenient table,
// and the bindings of the conditional priors whose conditions hold add their terms. The
// refresh rides on the next proposal (a rejection undoes it and it stays due). It changes the
// target (like a tempering step): its own jump of log p(W) on the current world is added to a
// running offset that log_prior() subtracts, so the engine's acceptance ratio compares M' with
// M under the refreshed target and its best state is tracked along one continuous scale.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "runtime/mcmc/model.h"
#include "stdlib/indoor/blocks.h"
#include "stdlib/indoor/kernels.h"
#include "stdlib/indoor/kit/door_cache.h"
#include "stdlib/indoor/kit/plan.h"
#include "stdlib/indoor/kit/semantic_layer.h"
#include "stdlib/indoor/scored_world.h"

namespace ksmc::stdlib::indoor::kit {

struct RunTuning {
  std::uint64_t semantic_every = 500;   // proposals between semantic refreshes (0 = never)
  std::uint64_t semantic_after = 0;     // first proposal with a semantic refresh
  std::uint64_t source_refresh = 200;   // proposals between FSU / door candidate refreshes
  std::size_t semantic_max_units = 80;  // worlds with more units skip the refresh (cost bound)
};

// Everything the chains share (read-only after construction).
struct SharedInput {
  std::shared_ptr<const blocks::Binding> binding;
  KitPlan plan;  // points into *binding
  ClassGrid grid;
  double resolution = 0.05;
  RunTuning tuning;
  ScoreParams score;
  KernelParams kernel;                                  // shift_sigma: per pool, see pool_kernel_params
  std::vector<std::vector<CandidateUnit>> fixed_units;  // per pool: WBU + RPB candidates
  double frame_deg = 0.0;                               // dominant orientation (FSU frame)
  std::unique_ptr<MapEvidence> evidence;
  std::uint64_t seed = 1;
};

class IndoorModel final : public runtime::mcmc::Model {
 public:
  explicit IndoorModel(std::shared_ptr<const SharedInput> in);
  ~IndoorModel() override;

  double log_likelihood() const override { return sw_.log_likelihood(); }
  // log p(W) of the current target minus target_offset(): the sum of the log-posterior jumps
  // of the semantic refreshes, so that the engine's running value, its acceptance ratios and
  // its best state stay comparable across refreshes (see the header comment).
  double log_prior() const override { return sw_.log_prior() + term_log_prior_ - offset_; }
  double target_offset() const { return offset_; }
  // log p(D|W) + log p(W) under the current target, without the offset.
  double true_log_posterior() const { return sw_.log_likelihood() + sw_.log_prior() + term_log_prior_; }
  void accept() override;
  void reject() override;
  runtime::mcmc::Snapshot snapshot() const override;
  void restore(const runtime::mcmc::Snapshot& s) override;

  // One proposal of the kernel declared `kernel`-th (KitPlan::kernels; called by the kernel
  // adapters). false: declined, untouched.
  bool propose(std::size_t kernel, runtime::mcmc::Rng& rng, double& log_q_fwd, double& log_q_bwd);

  const ScoredWorld& scored() const { return sw_; }
  const SharedInput& input() const { return *in_; }
  SemanticLayer* semantics() { return sem_ ? &*sem_ : nullptr; }
  // Runs the semantic layer on the current state now (outside any proposal): for results.
  std::optional<SemanticResult> final_semantics();
  std::uint64_t proposals() const { return iteration_; }

 private:
  struct Pool;
  void refresh_sources();
  std::vector<UnitChange> relabel(const SemanticResult& r) const;

  std::shared_ptr<const SharedInput> in_;
  ScoredWorld sw_;
  std::vector<std::unique_ptr<Pool>> pools_;
  std::optional<SemanticLayer> sem_;
  std::mt19937_64 krng_;
  bool krng_seeded_ = false;
  std::uint64_t iteration_ = 0;
  bool semantic_due_ = false;
  // The due refresh's inference on the current world: a rejected or declined proposal leaves
  // the world as it was, so the retry reuses it (cleared when a proposal is accepted).
  std::optional<SemanticResult> due_result_;
  // Semantic state: the conditional prior bindings of the last refresh and their sum.
  std::vector<PriorBinding> terms_;
  double term_log_prior_ = 0.0;
  double offset_ = 0.0;
  // Pending proposal.
  struct Pending {
    std::optional<Move> relabel, move;
    std::vector<PriorBinding> old_terms;
    double old_term = 0.0;
    double old_offset = 0.0;
    bool refresh = false;
    bool previewed = false;  // `move` is an open ScoredWorld preview (commit on accept)
  };
  std::optional<Pending> pending_;
};

// The engine-side kernel: one kernel declaration under its name.
class IndoorKernel final : public runtime::mcmc::NamedKernel<IndoorModel> {
 public:
  IndoorKernel(std::string name, std::string reverse, std::size_t index)
      : NamedKernel(std::move(name), std::move(reverse)), index_(index) {}

 protected:
  runtime::mcmc::Proposal propose_typed(IndoorModel& m, runtime::mcmc::Rng& rng) const override {
    double f = 0.0, b = 0.0;
    if (!m.propose(index_, rng, f, b)) return runtime::mcmc::Proposal::declined();
    return runtime::mcmc::Proposal::made(f, b);
  }

 private:
  std::size_t index_;
};

}  // namespace ksmc::stdlib::indoor::kit
