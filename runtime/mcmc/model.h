// The model and kernel contract between the MH engine and a domain.
//
// The compiler generates one Model subclass per domain (<domain>_model.cpp); the
// stdlib supplies kernels. The engine drives them like this, every iteration:
//
//   kernel = schedule.pick(iteration)
//   p      = kernel.propose(model, rng)      // model now holds the TENTATIVE state M'
//   if p.status == declined:  count, nothing to undo (the kernel changed nothing)
//   else:  lp' = model.log_likelihood() + model.log_prior()
//          accept with min(1, exp(lp' - lp + p.log_q_bwd - p.log_q_fwd
//                                 + log Phi(reverse) - log Phi(kernel)))
//          model.accept()  or  model.reject()  // reject restores M exactly
//
// Incremental evaluation is the model's business: a proposal should update only the
// terms it touches (a wall shift re-scores the cells of one wall), keep enough to undo
// them, and report the new totals in O(1). The engine never asks for a full re-score.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/mcmc/rng.h"

namespace ksmc::runtime::mcmc {

// A model state as a value: what the engine keeps for the best state and for posterior
// samples, and what a result writer reads. Must round-trip through Model::restore.
using Snapshot = nlohmann::json;

class Model {
 public:
  virtual ~Model() = default;

  // Log likelihood log p(D|M) and log prior log p(M) of the current state; during a
  // proposal (between propose and accept/reject) of the tentative state. Either may be
  // -infinity (impossible state: always rejected). Must be O(1): maintained incrementally.
  virtual double log_likelihood() const = 0;
  virtual double log_prior() const = 0;
  double log_posterior() const { return log_likelihood() + log_prior(); }

  // Ends a proposal: keep the tentative state, or restore the state before propose
  // (bit-identical log_likelihood/log_prior included).
  virtual void accept() = 0;
  virtual void reject() = 0;

  // State as a value, and back. restore() replaces the whole state (and recomputes the
  // cached terms from scratch); it is never called in the middle of a proposal.
  virtual Snapshot snapshot() const = 0;
  virtual void restore(const Snapshot& state) = 0;

  Model() = default;
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;
};

struct Proposal {
  enum class Status { proposed, declined };
  Status status = Status::declined;
  double log_q_fwd = 0.0;  // log Q(M'|M), given that this kernel was selected
  double log_q_bwd = 0.0;  // log Q(M|M'), given that the reverse kernel was selected
  // Delayed acceptance (Christen & Fox 2005): a model may first test the proposal against a
  // cheap part of its posterior, with a log ratio r1 that changes sign for the reverse move
  // (e.g. Δ cheap log posterior + log_q_bwd - log_q_fwd), and decline it when that test fails.
  // A proposal that passed reports r1 here; the engine's test is then the second stage,
  // log α - r1 (for a posterior = cheap part x expensive part: the expensive part's ratio).
  double log_screened = 0.0;

  static Proposal made(double log_q_fwd, double log_q_bwd, double log_screened = 0.0) {
    return Proposal{Status::proposed, log_q_fwd, log_q_bwd, log_screened};
  }
  // The kernel cannot apply here (e.g. MERGE with a single unit). The model must be
  // left untouched; the engine counts it as a rejection.
  static Proposal declined() { return Proposal{}; }
  bool was_declined() const { return status == Status::declined; }
};

// A sub-kernel. Kernels come in reversible pairs: name() / reverse_name() (ADD/REMOVE,
// SPLIT/MERGE, SHRINK/DILATE, ALLOCATE/DELETE); INTERCHANGE is its own reverse.
// Kernels are shared by all chains and called concurrently: propose() is const, and
// per-chain scratch belongs in the Model.
class Kernel {
 public:
  virtual ~Kernel() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view reverse_name() const = 0;
  // Applies a tentative change to `model` and returns its proposal densities, or
  // declines without touching the model. log_q_fwd is the probability of producing M'
  // from M with THIS kernel; log_q_bwd the probability of producing M from M' with the
  // REVERSE kernel (the schedule's kernel-selection probabilities are added by the
  // engine, not here).
  virtual Proposal propose(Model& model, Rng& rng) const = 0;
};

// Convenience base for kernels written against one concrete model type: the engine
// only ever passes the models made by the domain's own factory.
template <class M>
class TypedKernel : public Kernel {
 public:
  Proposal propose(Model& model, Rng& rng) const final {
    return propose_typed(static_cast<M&>(model), rng);
  }

 protected:
  virtual Proposal propose_typed(M& model, Rng& rng) const = 0;
};

// Kernel with its names given at construction (handy for generated code and tests).
template <class M>
class NamedKernel : public TypedKernel<M> {
 public:
  NamedKernel(std::string name, std::string reverse)
      : name_(std::move(name)), reverse_(std::move(reverse)) {}
  std::string_view name() const final { return name_; }
  std::string_view reverse_name() const final { return reverse_; }

 private:
  std::string name_;
  std::string reverse_;
};

// Makes the model of chain `chain` (one instance per chain; called on the chain's thread).
using ModelFactory = std::function<std::unique_ptr<Model>(unsigned chain)>;
// The kernel table, shared by all chains.
using KernelList = std::vector<std::shared_ptr<const Kernel>>;

}  // namespace ksmc::runtime::mcmc
