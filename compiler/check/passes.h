// The semantic check passes, in the order compiler/driver/pipeline.cpp runs them. Each one
// is a named object with one job; they share the symbol table built by SymbolsPass.
#pragma once

#include "compiler/check/pass.h"

namespace ksmc::compiler::check {

// Builds the symbol table; duplicated names, bad extern kinds, bad unit definitions.
class SymbolsPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "symbols"; }
  void run(Context& ctx) override;
};

// Undeclared names: types, predicates, kernels, model variables referenced by declarations.
class NamesPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "names"; }
  void run(Context& ctx) override;
};

// Atom arity and argument types (constants of enumerated types), `exactly one of` shape.
class ArityPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "arity"; }
  void run(Context& ctx) override;
};

// A variable used with two different types within one rule / extractor / prior.
class VariableTypesPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "variable-types"; }
  void run(Context& ctx) override;
};

// Rule weights: `prob` in (0, 1), no weight on hard rules, every rule weighted.
class WeightsPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "weights"; }
  void run(Context& ctx) override;
};

// `extract` targets: an evidence predicate over distinct variables, extracted once.
// Names every rule of the main file (compiler/check/rule_names.h) into SymbolTable::rule_names;
// a duplicate name is an error at the second rule.
class RuleNamesPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "rule-names"; }
  void run(Context& ctx) override;
};

// Kit contract: parameter ranges (after unit conversion), list shapes, row sums, label sets;
// signatures' own bounds and defaults.
class ContractParamsPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "contract-params"; }
  [[nodiscard]] bool needs_clean_input() const override { return true; }
  void run(Context& ctx) override;
};

// Kit contract: the model block against `extern model(...)`, one run-time type, `reads`.
class ModelContractPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "model-contract"; }
  [[nodiscard]] bool needs_clean_input() const override { return true; }
  void run(Context& ctx) override;
};

// Kit contract: the move each kernel's sources make (`makes` / `serves`) and the kernel shape.
class KernelMovesPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "kernel-moves"; }
  [[nodiscard]] bool needs_clean_input() const override { return true; }
  void run(Context& ctx) override;
};

// One likelihood; `prior for` with per-binding terms, plain `prior` with global ones.
class DomainItemsPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "domain-items"; }
  [[nodiscard]] bool needs_clean_input() const override { return true; }
  void run(Context& ctx) override;
};

class ExtractPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "extract"; }
  void run(Context& ctx) override;
};

// Calls of stdlib externs: known name of the right kind, parameters known / given once /
// not missing, argument types and unit dimensions; prior where-conditions.
class CallsPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "calls"; }
  void run(Context& ctx) override;
};

// Every kernel has a declared reverse, and reverses agree.
class KernelsPass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "kernels"; }
  void run(Context& ctx) override;
};

// Schedule rows: contiguous ranges from 0 to inf, probabilities sum to 1, reverses present.
class SchedulePass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "schedule"; }
  void run(Context& ctx) override;
};

// Warnings: query predicates in no rule, declarations never used.
class UsagePass final : public Pass {
 public:
  [[nodiscard]] std::string_view name() const override { return "usage"; }
  [[nodiscard]] bool needs_clean_input() const override { return true; }
  void run(Context& ctx) override;
};

}  // namespace ksmc::compiler::check
