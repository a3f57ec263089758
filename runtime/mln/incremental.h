// Incremental re-inference: a kit keeps one IncrementalInference per scene and tells
// it which evidence atoms changed; it re-grounds, and re-solves only the connected
// components whose content (atoms, clauses, weights, blocks, all named by query index,
// so independent of network numbering) differs from the previous network's. For a
// changed component with the same variables as before (e.g. a unit's geometry evidence
// changed: only unit clauses differ), the previous elimination plan (min-fill order and
// junction tree) is reused when every clause still fits a cluster.
//
// The result is the same as infer(method = auto) on the new network (exact components
// bit for bit, since each is solved by the same code on the same content).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "runtime/mln/evidence.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/inference.h"

namespace ksmc::runtime::mln {

struct EvidenceChange {
  std::int32_t predicate = 0;
  std::vector<std::int32_t> args;           // constant indices
  std::int8_t value = Evidence::kUnknown;   // 1, 0, or unknown (query predicates)
};

struct IncrementalStats {
  std::int32_t components = 0;
  std::int32_t reused = 0;        // results taken from the previous network
  std::int32_t solved = 0;        // re-solved exactly or sampled
  std::int32_t plans_reused = 0;  // of the eliminated ones: plan reused
};

class IncrementalInference {
 public:
  using Grounder = std::function<Grounding(const Domain&, const Evidence&)>;

  // Grounds with `grounder` (default: the generic ground(program, domain, evidence))
  // and infers everything. `program` and `domain` must outlive this object.
  IncrementalInference(const Program& program, const Domain& domain, const Evidence& evidence,
                       InferenceOptions options = {}, Grounder grounder = {});

  // Applies the changes to the evidence, re-grounds, re-infers the affected components.
  const InferenceResult& update(std::span<const EvidenceChange> changes);

  const InferenceResult& result() const { return result_; }
  const Grounding& grounding() const { return grounding_; }
  const Evidence& evidence() const { return evidence_; }
  const IncrementalStats& stats() const { return stats_; }

 private:
  struct Cached {
    std::vector<double> marginals;  // per component atom (local order)
    double log_z = 0.0;
    bool exact = true;
    std::int64_t samples = 0;
  };
  struct CachedPlan {
    Component comp;  // the component the plan was made for (its global ids)
    EliminationPlan plan;
  };
  void run();

  const Program& program_;
  const Domain& domain_;
  Evidence evidence_;
  InferenceOptions options_;
  Grounder grounder_;
  Grounding grounding_;
  InferenceResult result_;
  IncrementalStats stats_;
  std::map<std::vector<std::int64_t>, Cached> results_;    // by full component content
  std::map<std::vector<std::int64_t>, CachedPlan> plans_;  // by component variables
};

}  // namespace ksmc::runtime::mln
