// The indoor model behind the runtime/mcmc engine: a ScoredWorld (incremental likelihood +
// weak prior), one KernelSet per source pool (each kernel draws from the proposal sources its
// declaration names, KitPlan), plus the semantic layer. The target is one fixed posterior:
//   log p(W|M) = log p(M|W, types(W)) + weak prior(W) + knowledge(W)
// where types(W) are the most probable unit types Markov logic gives for the evidence of W
// (units of a lenient type use the lenient table) and knowledge(W) is the sum of the
// conditional prior terms whose conditions hold plus, with `prior mln`, the Markov logic score
// of the evidence. Every proposal evaluates it on the proposed world: the evidence atoms of
// the units the move touched are re-extracted, inference is recalled from the evidence cache
// or run exactly (runtime/mln, per component), units whose type changed switch tables inside
// the same proposal. A world whose evidence violates a hard rule has probability 0.
// When the tables do not depend on the types (KitPlan::type_free_likelihood) a proposal is
// first tested on the likelihood and weak prior alone (delayed acceptance, Christen & Fox
// 2005: runtime/mcmc Proposal::log_screened); only the proposals that pass it pay for the
// knowledge part, whose ratio the engine then tests. The chain's target is unchanged.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "runtime/mcmc/model.h"
#include "stdlib/indoor/blocks.h"
#include "stdlib/indoor/kernels.h"
#include "stdlib/indoor/kit/plan.h"
#include "stdlib/indoor/kit/semantic_layer.h"
#include "stdlib/indoor/scored_world.h"

namespace ksmc::stdlib::indoor::kit {

struct RunTuning {
  std::uint64_t source_refresh = 200;  // proposals between FSU / door candidate refreshes
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
  cv::Mat1f free_distance;  // free_distance(grid): the field geom.hollow reads, once per map
  std::uint64_t seed = 1;
};

class IndoorModel final : public runtime::mcmc::Model {
 public:
  explicit IndoorModel(std::shared_ptr<const SharedInput> in);
  ~IndoorModel() override;

  double log_likelihood() const override { return sw_.log_likelihood(); }
  double log_prior() const override { return sw_.log_prior() + knowledge_; }
  // The knowledge part of log p(W) (see the header comment); -inf for an impossible world.
  double log_knowledge() const { return knowledge_; }
  void accept() override;
  void reject() override;
  runtime::mcmc::Snapshot snapshot() const override;
  void restore(const runtime::mcmc::Snapshot& s) override;

  // One proposal of the kernel declared `kernel`-th (KitPlan::kernels; called by the kernel
  // adapters). false: declined, untouched.
  // log_screened: the first stage's log ratio when the proposal passed it (else 0).
  bool propose(std::size_t kernel, runtime::mcmc::Rng& rng, double& log_q_fwd, double& log_q_bwd, double& log_screened);
  // Applies `move` (valid on the current world) when the world after it has a higher log
  // posterior, the knowledge part included (evaluated as a proposal is: incrementally); else
  // leaves the state as it was. Not during a proposal. For the search after the run (after_run.h).
  bool improve(const Move& move);
  // Proposals declined by the first stage of delayed acceptance so far.
  std::uint64_t screened_out() const { return screened_out_; }

  const ScoredWorld& scored() const { return sw_; }
  const SharedInput& input() const { return *in_; }
  SemanticLayer* semantics() { return sem_ ? &*sem_ : nullptr; }
  // The semantic layer's result for the current state (nullopt without a rule base).
  std::optional<SemanticResult> final_semantics() const { return current_; }
  std::uint64_t proposals() const { return iteration_; }

 private:
  struct Pool;
  void refresh_sources();
  // Makes `r` (the semantics of the current world) current: switches the tables of the units
  // whose type changed (returns that move, applied) and sets the knowledge term.
  std::optional<Move> adopt(SemanticResult r, KernelKind kind);
  std::vector<UnitChange> relabel(const SemanticResult& r) const;
  struct Pending;
  // The knowledge part of a move already previewed or applied (pend.previewed says which):
  // re-infers what the move touched, switches tables, and makes the move pending.
  void stage(Pending pend, Move move, KernelKind k);

  std::shared_ptr<const SharedInput> in_;
  ScoredWorld sw_;
  std::vector<std::unique_ptr<Pool>> pools_;
  std::optional<SemanticLayer> sem_;
  std::mt19937_64 krng_;
  bool krng_seeded_ = false;
  std::uint64_t iteration_ = 0;
  std::uint64_t screened_out_ = 0;
  std::optional<SemanticResult> current_;  // semantics of the current world
  double knowledge_ = 0.0;                 // current_->log_knowledge()
  // Pending proposal.
  struct Pending {
    std::optional<Move> relabel, move;
    std::optional<SemanticResult> old_semantics;
    double old_knowledge = 0.0;
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
    double f = 0.0, b = 0.0, screened = 0.0;
    if (!m.propose(index_, rng, f, b, screened)) return runtime::mcmc::Proposal::declined();
    return runtime::mcmc::Proposal::made(f, b, screened);
  }

 private:
  std::size_t index_;
};

}  // namespace ksmc::stdlib::indoor::kit
