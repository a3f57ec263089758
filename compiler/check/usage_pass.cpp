#include <set>

#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

namespace {

void collect_expr_names(const ast::Expr& e, std::set<std::string>& names) {
  if (e.kind == ast::Expr::Kind::Name || e.kind == ast::Expr::Kind::Index) names.insert(e.text);
  if (e.kind == ast::Expr::Kind::Call) {
    for (const ast::Arg& a : e.call->args) collect_expr_names(a.value, names);
  }
  for (const ast::Expr& i : e.items) collect_expr_names(i, names);
}

}  // namespace

void UsagePass::run(Context& ctx) {
  if (ctx.program.modules.empty()) return;
  std::set<std::string> in_rules, extracted, used_types, used_names, scheduled;
  for (const ast::Module& m : ctx.program.modules) {
    for (const Scope& sc : collect_scopes(m)) {
      for (const ast::Atom* a : sc.atoms) {
        if (sc.kind == Scope::Kind::Rule) in_rules.insert(a->pred.name);
      }
      for (const ast::Call* c : sc.calls) {
        for (const ast::Arg& a : c->args) collect_expr_names(a.value, used_names);
      }
      for (const auto& [n, t] : sc.declared) used_types.insert(t);
    }
    for (const ast::Item& item : m.items) {
      if (const auto* e = std::get_if<ast::ExtractDecl>(&item.node)) extracted.insert(e->target.pred.name);
      if (const auto* d = std::get_if<ast::PredDecl>(&item.node)) {
        for (const ast::PredSig& p : d->preds) {
          for (const ast::PredArg& a : p.args) used_types.insert(a.type.name);
        }
      }
      if (const auto* md = std::get_if<ast::ModelDecl>(&item.node)) {
        for (const ast::ModelVar& v : md->vars) {
          if (v.index) used_types.insert(v.index->name);
        }
      }
      if (const auto* s = std::get_if<ast::ScheduleDecl>(&item.node)) {
        for (const ast::ScheduleRow& row : s->rows) {
          for (const ast::ScheduleEntry& e : row.entries) {
            if (e.prob.value > 0.0) scheduled.insert(e.kernel.name);
          }
        }
      }
    }
  }
  // A variable-size collection named like a type makes the type used (it supplies its constants).
  for (const auto& [name, mv] : ctx.symbols.model_vars) {
    if (!mv.element_type.empty()) used_types.insert(mv.element_type);
  }

  const ast::Module& main = ctx.main();
  // A pure rule base (no model, no likelihood: run by `ksmc infer` on .db evidence) has no
  // extractors by design.
  bool has_model = false;
  for (const ast::Item& item : main.items) {
    if (std::holds_alternative<ast::ModelDecl>(item.node) || std::holds_alternative<ast::LikelihoodDecl>(item.node))
      has_model = true;
  }
  for (const ast::Item& item : main.items) {
    if (const auto* d = std::get_if<ast::PredDecl>(&item.node)) {
      for (const ast::PredSig& p : d->preds) {
        if (in_rules.count(p.name.name) == 0) {
          ctx.diags.warning(p.name.loc, std::string(d->query ? "query" : "evidence") + " predicate '" + p.name.name +
                                            "' is not used in any rule");
        }
        if (has_model && !d->query && extracted.count(p.name.name) == 0) {
          ctx.diags.warning(p.name.loc, "evidence predicate '" + p.name.name + "' has no extractor");
        }
      }
    } else if (const auto* t = std::get_if<ast::TypeDecl>(&item.node)) {
      if (used_types.count(t->name.name) == 0) {
        ctx.diags.warning(t->name.loc, "type '" + t->name.name + "' is declared but never used");
      }
    } else if (const auto* md = std::get_if<ast::ModelDecl>(&item.node)) {
      for (const ast::ModelVar& v : md->vars) {
        if (used_names.count(v.name.name) == 0) {
          ctx.diags.warning(v.name.loc, "model variable '" + v.name.name + "' is never used");
        }
      }
    } else if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) {
      std::vector<const ast::Ident*> names{&k->name};
      if (k->pair && k->reverse && k->reverse->name != k->name.name) names.push_back(&*k->reverse);
      for (const ast::Ident* n : names) {
        if (scheduled.count(n->name) == 0) ctx.diags.warning(n->loc, "kernel '" + n->name + "' is never scheduled");
      }
    }
  }
}

}  // namespace ksmc::compiler::check
