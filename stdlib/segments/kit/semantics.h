// The semantic half of the segments model: the evidence relations of the domain file's
// extractors over the current lines, Markov logic inference over the generated factors
// (mln::infer, Method::Auto, log Z computed) cached by the exact evidence bits (LRU), the
// `prior mln` term log Z(evidence) - log Z(no relation holds) for the same number of lines,
// and the inference-driven Gaussian prior terms (`prior for a, b where P(...) > t: ...`).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "runtime/domain/config.h"
#include "runtime/mln/evidence_cache.h"
#include "stdlib/segments/kit/settings.h"
#include "stdlib/segments/scene.h"

namespace ksmc::stdlib::segments::kit {

struct MlnOutcome {
  std::size_t lines = 0;
  double log_z = 0.0;  // -inf when the evidence violates a hard rule
  // Per predicate of the program (program order): the truth of evidence atoms (0/1) or the
  // marginal of query atoms, flat over lines^arity (first argument most significant).
  std::vector<std::vector<double>> values;
  std::string method;
};

struct MlnStats {
  std::uint64_t lookups = 0, runs = 0, hits = 0;
  double run_seconds = 0.0;
};

class Semantics {
 public:
  // Throws ConfigError when the program does not fit the settings (an evidence predicate
  // without extractor, a predicate over another type, an unknown predicate in a condition).
  Semantics(const SegmentsSettings& settings, const runtime::domain::MlnBinding& binding,
            std::size_t cache_capacity = 256);

  std::shared_ptr<const MlnOutcome> evaluate(const std::vector<Line>& lines);
  // log Z of the all-false evidence for n lines (cached).
  double baseline_log_z(std::size_t n);

  // Sum of the semantic Gaussian terms for these lines and outcome.
  double semantic_terms(const std::vector<Line>& lines, const MlnOutcome& outcome) const;

  const runtime::mln::Program& program() const { return *program_; }
  const std::vector<std::int32_t>& query_predicates() const { return queries_; }
  const MlnStats& stats() const { return stats_; }

 private:
  std::vector<std::uint8_t> key(const std::vector<Line>& lines) const;
  std::shared_ptr<const MlnOutcome> run(const std::vector<std::uint8_t>& bits, std::size_t n);
  double value(const MlnOutcome& o, std::int32_t pred, const std::vector<std::size_t>& args) const;

  const SegmentsSettings& settings_;
  runtime::domain::MlnBinding binding_;
  const runtime::mln::Program* program_ = nullptr;
  std::int32_t type_ = 0;
  std::vector<std::int32_t> extract_pred_;  // per settings.extracts
  std::vector<std::int32_t> queries_;
  std::vector<std::vector<std::int32_t>> term_cond_pred_;  // per term, per condition
  runtime::mln::EvidenceCache<MlnOutcome> cache_;
  std::map<std::size_t, double> baseline_;
  MlnStats stats_;
};

}  // namespace ksmc::stdlib::segments::kit
