// The binding of a domain file to its stdlib kit: what generated `<domain>_model.cpp`
// fills in and a kit runs. It replaces the string-keyed DomainConfig table: every name of
// the `.ksm` (predicates, types, kernels) reaches the kit as an index or as data, and every
// stdlib call as a direct C++ call of the block it names (docs/extending.md).
//
//   extract P(a, b) = blk(x[a], x[b], k = 3);   ->  bool extract_P(const Scene&, const std::int32_t* c)
//                                                    { return blocks::blk(s, s.rect(c[0]), s.rect(c[1]), 3); }
//                                                    Extractor{kPred_P, &extract_P, "<item text>"}
//   prior for a, b where P(Q(a, b)) > t: term(...)   ConditionalPrior{var types, conditions, &prior_fn, text}
//   prior name(args);                            ->  blocks::name(args) appended to Binding::priors
//   likelihood name(args);                       ->  Binding::likelihood = blocks::name(args)
//   output name(args);                           ->  blocks::name(args) appended to Binding::outputs
//   kernel pair A / B = src(...), ...;           ->  two KernelDecl (A: forward move, B: reverse
//                                                    move) sharing the sources blocks::src(...)
//   schedule { [lo, hi): { A: p, ... }; }        ->  ScheduleRow{lo, hi, {{"A", p}, ...}}
//
// `ksmc check` has already enforced the kit contract declared in stdlib/<kit>.ksm (parameter
// kinds and ranges, table shapes, which moves a source makes, label sets), so a kit meets only
// values it can run. A ConfigError thrown by a kit at run time is therefore an internal
// error: the domain binary reports it as such (exit 3), never aborts.
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "runtime/domain/config_error.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/program.h"

namespace ksmc::runtime::domain {

// The generated Markov logic part of a domain (`<domain>_factors.h`).
struct MlnBinding {
  const mln::Program& (*program)() = nullptr;
  mln::Domain (*make_domain)() = nullptr;
  mln::Grounding (*ground)(const mln::Domain&, const mln::Evidence&) = nullptr;
};

enum class Cmp { gt, ge, lt, le };

// One condition of `prior for VARS where ...`: `P(Q(a, b)) > 0.5` (probability of a query
// atom) or `Adj(a, b)` / `!Adj(a, b)` (truth of an evidence atom). `vars` index the prior's
// variables (0 = first variable after `for`).
struct Condition {
  bool probability = false;
  std::int32_t predicate = -1;
  std::vector<int> vars;
  Cmp cmp = Cmp::gt;        // probability conditions
  double threshold = 0.0;   // probability conditions
  bool negated = false;     // atom conditions
};

// Truth of one ground evidence atom: `constants` are the constant indices of the atom's
// arguments (run-time constants of the kit's constant type in scene order, after any
// enumerated constants of that type).
template <class Scene>
using ExtractFn = bool (*)(const Scene& scene, const std::int32_t* constants);

template <class Scene>
struct Extractor {
  std::int32_t predicate = -1;
  ExtractFn<Scene> eval = nullptr;
  std::string text;  // the `extract` item as written (messages, dumps)
};

// The log-density contribution of one binding of a conditional prior whose conditions hold.
template <class Scene>
using TermFn = double (*)(const Scene& scene, const std::int32_t* constants);

template <class Scene>
struct ConditionalPrior {
  std::vector<std::int32_t> var_types;  // type id per variable after `for`
  std::vector<Condition> conditions;    // all must hold
  TermFn<Scene> eval = nullptr;
  std::string text;
};

// One direction of a kernel declaration. `kernel pair A / B = ...` gives A (the sources'
// forward move) and B (their reverse move); `kernel K reverse K = ...` gives K alone with
// the sources' self-reverse move. Both directions of a pair share `sources`.
template <class Move, class Source>
struct KernelDecl {
  std::string name;
  std::string reverse;
  Move move{};
  std::vector<Source> sources;
  std::string text;
};

struct ScheduleRow {
  static constexpr std::int64_t kForever = std::numeric_limits<std::int64_t>::max();
  std::int64_t begin = 0;
  std::int64_t end = kForever;  // exclusive
  std::vector<std::pair<std::string, double>> probabilities;  // kernel name, selection probability
};

// The semantic half every kit shares: the knowledge base and how its evidence is computed
// from the kit's scene. The constants of `constant_type` are the scene's elements (units,
// objects, lines) in scene order; run-time constants of other types are not supported.
template <class Scene>
struct SemanticBinding {
  MlnBinding mln;
  std::int32_t constant_type = -1;
  std::vector<Extractor<Scene>> extractors;            // source order
  std::vector<ConditionalPrior<Scene>> conditional_priors;  // source order
};

// The whole binding of one domain file to kit types: `Prior`, `Likelihood`, `Source` and
// `Output` are the kit's block values (usually std::variant of parameter structs), `Move`
// the kit's enum of moves its sources make.
template <class Scene, class Prior, class Likelihood, class Move, class Source, class Output>
struct Binding : SemanticBinding<Scene> {
  std::string domain;  // `domain NAME;`
  std::string source;  // the domain file as given to ksmc
  std::vector<Prior> priors;  // unconditional `prior` items, source order
  Likelihood likelihood{};
  std::vector<Output> outputs;
  std::vector<KernelDecl<Move, Source>> kernels;  // declaration order, pairs as two entries
  std::vector<ScheduleRow> schedule;
};

}  // namespace ksmc::runtime::domain
