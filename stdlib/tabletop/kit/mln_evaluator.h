// Markov logic inside the sampler loop: the table-top evidence (stdlib/tabletop/evidence.h)
// as evidence bits of the generated program, grounded and inferred only when those bits
// change. Results are cached in a small LRU keyed by a hash of the bits plus an exact
// comparison, so revisiting an evidence configuration (the common case: most pose moves
// leave every relation as it was) costs one hash and one compare.
//
// Inference: mln::infer with Method::Auto (exact per component when small, MC-SAT
// otherwise) and compute_log_z for the marginals and log Z (the log of the sum over the
// query worlds of exp(Σ w n) given the evidence, the network's folded constant included),
// and mln::exact_map (MaxWalkSAT for a component too large) for log_map, the log-weight
// Σ w n of the most probable world. Either is the `prior mln` term (KitConfig::
// prior_quantity, docs/tabletop_kit.md). Seeds are fixed, so an outcome is a pure function
// of the evidence bits and the cache never changes results.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "runtime/domain/config.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/evidence_cache.h"
#include "runtime/mln/program.h"
#include "stdlib/tabletop/evidence.h"

namespace ksmc::stdlib::tabletop::kit {

struct MlnOutcome {
  double log_z = 0.0;               // −inf when the evidence violates a hard rule
  double log_map = 0.0;             // Σ w n of the most probable query world (−inf likewise)
  bool log_map_exact = true;        // false: MaxWalkSAT (a component too large to enumerate)
  std::vector<double> false_prob;   // P(falseEst(body)), per body (0 = table)
  std::vector<double> hidden_prob;  // P(hidden(body))
  std::string method;
  bool log_z_exact = true;
};

struct MlnStats {
  std::uint64_t lookups = 0;
  std::uint64_t runs = 0;  // groundings + inferences actually run
  std::uint64_t hits = 0;
  double seconds = 0.0;      // wall time inside evaluate (key hashing, lookups and runs)
  double run_seconds = 0.0;  // of which grounding + inference
};

class MlnEvaluator {
 public:
  // `body_ids`: "table" then the objects, as in Evidence::ids. Throws ConfigError when the
  // program lacks a predicate the kit fills or queries.
  MlnEvaluator(const runtime::domain::MlnBinding& binding, const std::vector<std::string>& body_ids,
               std::size_t cache_capacity = 512);

  // Evidence bits of `ev` (closed world: every atom of the six evidence predicates).
  std::vector<std::uint8_t> key(const Evidence& ev) const;
  // The outcome for these evidence bits (cached).
  std::shared_ptr<const MlnOutcome> evaluate(const Evidence& ev);
  std::shared_ptr<const MlnOutcome> evaluate_key(const std::vector<std::uint8_t>& bits);

  const MlnStats& stats() const noexcept { return stats_; }
  std::size_t bodies() const noexcept { return n_; }

 private:
  std::shared_ptr<const MlnOutcome> lookup(const std::vector<std::uint8_t>& bits);
  std::shared_ptr<const MlnOutcome> run(const std::vector<std::uint8_t>& bits);

  const runtime::domain::MlnBinding binding_;
  std::size_t n_ = 0;
  runtime::mln::Domain domain_;
  std::int32_t p_stable_, p_table_, p_hover_, p_contact_, p_intersect_, p_higher_, p_false_, p_hidden_;
  runtime::mln::EvidenceCache<MlnOutcome> cache_;
  MlnStats stats_;
};

}  // namespace ksmc::stdlib::tabletop::kit
