#include "compiler/driver/pipeline.h"

#include <algorithm>
#include <set>

#include "compiler/check/passes.h"
#include "compiler/emit/emit_model.h"
#include "compiler/lower/lower_domain.h"
#include "compiler/lower/lower_mln.h"

namespace ksmc::compiler::driver {

std::vector<std::unique_ptr<check::Pass>> make_check_passes() {
  std::vector<std::unique_ptr<check::Pass>> p;
  p.push_back(std::make_unique<check::SymbolsPass>());
  p.push_back(std::make_unique<check::NamesPass>());
  p.push_back(std::make_unique<check::ArityPass>());
  p.push_back(std::make_unique<check::VariableTypesPass>());
  p.push_back(std::make_unique<check::WeightsPass>());
  p.push_back(std::make_unique<check::RuleNamesPass>());
  p.push_back(std::make_unique<check::ExtractPass>());
  p.push_back(std::make_unique<check::CallsPass>());
  p.push_back(std::make_unique<check::KernelsPass>());
  p.push_back(std::make_unique<check::ContractParamsPass>());
  p.push_back(std::make_unique<check::ModelContractPass>());
  p.push_back(std::make_unique<check::KernelMovesPass>());
  p.push_back(std::make_unique<check::DomainItemsPass>());
  p.push_back(std::make_unique<check::SchedulePass>());
  p.push_back(std::make_unique<check::UsagePass>());
  return p;
}

std::vector<std::string> pass_names() {
  std::vector<std::string> names{"parse", "build"};
  for (const auto& p : make_check_passes()) names.emplace_back("check:" + std::string(p->name()));
  for (const char* back : {"lower:mln", "lower:domain", "emit:factors", "emit:model"}) names.emplace_back(back);
  return names;
}

bool run_checks(const ast::Program& program, diag::DiagEngine& diags, check::SymbolTable& symbols) {
  if (program.modules.empty()) return false;
  check::Context ctx{program, diags, {}};
  const int before = diags.error_count();
  for (const auto& pass : make_check_passes()) {
    // Contract checks and unused-declaration warnings are noise while there are errors.
    if (pass->needs_clean_input() && diags.error_count() > before) continue;
    pass->run(ctx);
  }
  symbols = std::move(ctx.symbols);
  return diags.error_count() == before;
}

FrontendResult run_frontend(const std::string& path, const build::LoadOptions& options, diag::SourceManager& sources,
                            diag::DiagEngine& diags, const std::string* text) {
  FrontendResult r;
  r.loaded = text != nullptr ? build::load_program_text(path, *text, options, sources, diags, r.program)
                             : build::load_program(path, options, sources, diags, r.program);
  if (!r.loaded) return r;
  r.ok = run_checks(r.program, diags, r.symbols);
  return r;
}

PipelineResult run_pipeline(const std::string& path, const build::LoadOptions& options, diag::SourceManager& sources,
                            diag::DiagEngine& diags, Goal goal, const std::string* text) {
  PipelineResult r;
  r.front = run_frontend(path, options, sources, diags, text);
  if (!r.front.ok) return r;
  if (goal == Goal::Check) {
    r.ok = true;
    return r;
  }
  // lower:mln
  if (!lower::lower_mln(r.front.program, r.front.symbols, sources, diags, r.mln) || diags.has_errors()) return r;
  if (goal == Goal::LowerMln) {
    r.ok = true;
    return r;
  }
  // lower:domain
  r.domain = lower::lower_domain(r.front.program, r.front.symbols, sources);
  if (goal == Goal::Lower) {
    r.ok = true;
    return r;
  }
  // emit:factors, emit:model
  const emit::FactorsOutput factors = emit::emit_factors(r.mln);
  r.files.push_back(factors.header);
  r.files.push_back(factors.source);
  if (!r.domain.kit.empty()) {
    emit::ModelOutput model = emit::emit_model(r.domain);
    r.files.push_back(std::move(model.header));
    r.files.push_back(std::move(model.source));
    r.files.push_back(std::move(model.main));
  }
  r.ok = true;
  return r;
}

std::string summary(const ast::Module& main, const check::SymbolTable& symbols) {
  int rules = 0, evidence = 0, query = 0, pairs = 0, phases = 0;
  for (const ast::Item& item : main.items) {
    if (std::holds_alternative<ast::Rule>(item.node)) ++rules;
    if (const auto* d = std::get_if<ast::PredDecl>(&item.node)) {
      (d->query ? query : evidence) += static_cast<int>(d->preds.size());
    }
    if (const auto* s = std::get_if<ast::ScheduleDecl>(&item.node)) phases += static_cast<int>(s->rows.size());
  }
  // A pair is an unordered {kernel, reverse}; a self-reverse kernel is one pair.
  std::set<std::pair<std::string, std::string>> unordered;
  for (const auto& [name, k] : symbols.kernels) {
    if (k.module != 0) continue;
    const std::string rev = k.reverse ? k.reverse->name : name;
    unordered.insert(std::minmax(name, rev));
  }
  pairs = static_cast<int>(unordered.size());
  auto n = [](int v, const char* one, const char* many) { return std::to_string(v) + " " + (v == 1 ? one : many); };
  return n(rules, "rule", "rules") + ", " + std::to_string(evidence) + " evidence, " +
         n(query, "query predicate", "query predicates") + ", " + n(pairs, "kernel pair", "kernel pairs") + ", " +
         n(phases, "schedule phase", "schedule phases");
}

}  // namespace ksmc::compiler::driver
