// The indoor model behind the runtime/mcmc engine: a ScoredWorld (incremental likelihood +
// weak prior) and its own KernelSet (sources read per-chain caches), plus the semantic layer:
// every `semantic_every` proposals the Markov logic types of the units are refreshed (cached by
// evidence) and folded into that proposal: units typed Room/Hall (the lenient types) switch to
// the lenient likelihood table, and the pairs with P(SaLe) above the threshold get the Gaussian
// wall-length prior. The refresh rides on the next proposal (a rejection undoes it and it
// stays due). It changes the target (like a tempering step): its own jump of log p(W) on the
// current world is added to a running offset that log_prior() subtracts, so the engine's
// acceptance ratio compares M' with M under the refreshed target and its best state is
// tracked along one continuous scale.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "runtime/mcmc/model.h"
#include "stdlib/indoor/kernels.h"
#include "stdlib/indoor/kit/door_cache.h"
#include "stdlib/indoor/kit/semantics.h"
#include "stdlib/indoor/kit/settings.h"
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
  ClassGrid grid;
  double resolution = 0.05;
  IndoorSettings settings;
  RunTuning tuning;
  ScoreParams score;
  KernelParams kernel;
  std::vector<CandidateUnit> fixed_units;  // WBU + RPB candidates
  double frame_deg = 0.0;                  // dominant orientation (FSU frame)
  std::unique_ptr<MapEvidence> evidence;
  runtime::domain::MlnBinding binding;
  std::uint64_t seed = 1;
};

class IndoorModel final : public runtime::mcmc::Model {
 public:
  explicit IndoorModel(std::shared_ptr<const SharedInput> in);

  double log_likelihood() const override { return sw_.log_likelihood(); }
  // log p(W) of the current target minus target_offset(): the sum of the log-posterior jumps
  // of the semantic refreshes, so that the engine's running value, its acceptance ratios and
  // its best state stay comparable across refreshes (see the header comment).
  double log_prior() const override { return sw_.log_prior() + sale_log_prior_ - offset_; }
  double target_offset() const { return offset_; }
  // log p(D|W) + log p(W) under the current target, without the offset.
  double true_log_posterior() const { return sw_.log_likelihood() + sw_.log_prior() + sale_log_prior_; }
  void accept() override;
  void reject() override;
  runtime::mcmc::Snapshot snapshot() const override;
  void restore(const runtime::mcmc::Snapshot& s) override;

  // One proposal of kernel `k` (called by the kernel adapters). false: declined, untouched.
  bool propose(KernelKind k, runtime::mcmc::Rng& rng, double& log_q_fwd, double& log_q_bwd);

  const ScoredWorld& scored() const { return sw_; }
  const SharedInput& input() const { return *in_; }
  SemanticEngine* semantics() { return sem_ ? &*sem_ : nullptr; }
  // Runs the semantic layer on the current state now (outside any proposal): for results.
  std::optional<SemanticResult> final_semantics();
  std::uint64_t proposals() const { return iteration_; }

 private:
  void refresh_sources();
  double sale_log_prior(const World& w) const;
  std::vector<UnitChange> relabel(const SemanticResult& r) const;

  std::shared_ptr<const SharedInput> in_;
  ScoredWorld sw_;
  std::unique_ptr<KernelSet> ks_;
  std::optional<SemanticEngine> sem_;
  std::mt19937_64 krng_;
  bool krng_seeded_ = false;
  std::uint64_t iteration_ = 0;
  bool semantic_due_ = false;
  // The due refresh's inference on the current world: a rejected or declined proposal leaves
  // the world as it was, so the retry reuses it (cleared when a proposal is accepted).
  std::optional<SemanticResult> due_result_;
  // Sources.
  std::vector<CandidateUnit> units_;
  std::vector<CandidateDoor> doors_;
  DoorCandidateCache door_cache_;
  std::map<std::tuple<double, double, double, double, double>, std::vector<CandidateLine>> splits_;
  // Semantic state.
  std::vector<std::pair<UnitId, UnitId>> sale_pairs_;
  double sale_log_prior_ = 0.0;
  double offset_ = 0.0;
  // Pending proposal.
  struct Pending {
    std::optional<Move> relabel, move;
    std::vector<std::pair<UnitId, UnitId>> old_pairs;
    double old_sale = 0.0;
    double old_offset = 0.0;
    bool refresh = false;
    bool previewed = false;  // `move` is an open ScoredWorld preview (commit on accept)
  };
  std::optional<Pending> pending_;
};

// The engine-side kernel: one KernelKind under its .ksm name.
class IndoorKernel final : public runtime::mcmc::NamedKernel<IndoorModel> {
 public:
  IndoorKernel(std::string name, std::string reverse, KernelKind kind)
      : NamedKernel(std::move(name), std::move(reverse)), kind_(kind) {}

 protected:
  runtime::mcmc::Proposal propose_typed(IndoorModel& m, runtime::mcmc::Rng& rng) const override {
    double f = 0.0, b = 0.0;
    if (!m.propose(kind_, rng, f, b)) return runtime::mcmc::Proposal::declined();
    return runtime::mcmc::Proposal::made(f, b);
  }

 private:
  KernelKind kind_;
};

// "ADD" -> KernelKind::Add, ...; nullopt for other names.
std::optional<KernelKind> kernel_kind(const std::string& name);

}  // namespace ksmc::stdlib::indoor::kit
