// The model half of the kit contract: the domain's `model` block declares exactly the
// variables of the kit's `extern model(...)` (value type, indexing, sampled / fixed; names
// and order free), its run-time constants are of one type, and every block that `reads T[]`
// finds a model collection of T.
#include <set>

#include "compiler/check/call_binding.h"
#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {
namespace {

std::string slot_text(const ast::ModelSlot& s) {
  std::string t = s.type.name;
  if (s.collection) t += "[" + (s.index ? s.index->name : std::string()) + "]";
  return t + (s.sampled ? " sampled" : " fixed");
}

std::string var_text(const ast::ModelVar& v) {
  std::string t = v.type.name;
  if (v.collection) t += "[" + (v.index ? std::string("entity") : std::string()) + "]";
  return t + (v.sampled ? " sampled" : " fixed");
}

bool fits(const ast::ModelSlot& s, const ast::ModelVar& v, const SymbolTable& symbols) {
  if (s.type.name != v.type.name || v.type.list_depth != 0 || s.sampled != v.sampled || s.collection != v.collection) return false;
  if (!s.collection) return true;
  if (s.index.has_value() != v.index.has_value()) return false;
  if (!s.index) return true;
  return s.index->name == "entity" ? symbols.is_domain_type(v.index->name) : s.index->name == v.index->name;
}

void reads(Context& ctx, const ast::Call& c, const ast::ModelDecl* model) {
  auto it = ctx.symbols.externs.find(c.name);
  if (it == ctx.symbols.externs.end()) return;
  for (const BoundArg& b : bind_call(c, *it->second.decl))
    if (b.value != nullptr && b.value->kind == ast::Expr::Kind::Call) reads(ctx, *b.value->call, model);
  const auto& r = it->second.decl->reads;
  if (!r) return;
  bool found = false;
  for (std::size_t i = 0; model != nullptr && i < model->vars.size(); ++i)
    found = found || (model->vars[i].collection && model->vars[i].type.name == r->name);
  if (!found) {
    ctx.diags.error(c.loc, "'" + c.name + "' reads " + r->name + "[], but the model has no collection of '" + r->name +
                               "' (declare e.g. 'x[] : " + r->name + " sampled;')");
  }
}

}  // namespace

void ModelContractPass::run(Context& ctx) {
  const ast::ModelDecl* model = nullptr;
  ast::Loc model_loc;
  for (const ast::Item& item : ctx.main().items) {
    if (const auto* m = std::get_if<ast::ModelDecl>(&item.node); m != nullptr && model == nullptr) {
      model = m;
      model_loc = item.loc;
    }
  }
  for (const Scope& sc : collect_scopes(ctx.main()))
    for (const ast::Call* c : sc.calls) reads(ctx, *c, model);
  if (model == nullptr) {
    const ast::ModelContractDecl* contract = model_contract(ctx.program, ctx.symbols);
    for (const ast::Item& item : ctx.main().items) {
      if (contract != nullptr && std::holds_alternative<ast::LikelihoodDecl>(item.node)) {
        ctx.diags.error(item.loc, "the kit of this likelihood runs a model: declare 'model NAME { ... }' with the variables of its extern model(...)");
        break;
      }
    }
    return;
  }

  // One run-time type.
  std::string runtime_type;
  for (const ast::ModelVar& v : model->vars) {
    auto it = ctx.symbols.model_vars.find(v.name.name);
    if (it == ctx.symbols.model_vars.end() || !ctx.symbols.is_domain_type(it->second.element_type)) continue;
    if (runtime_type.empty()) {
      runtime_type = it->second.element_type;
    } else if (it->second.element_type != runtime_type) {
      ctx.diags.error(v.loc, "model variable '" + v.name.name + "' ranges over '" + it->second.element_type +
                                 "', but the model's run-time constants are of type '" + runtime_type +
                                 "' (a kit runs one type of run-time constants)");
    }
  }

  const ast::ModelContractDecl* contract = model_contract(ctx.program, ctx.symbols);
  if (contract == nullptr) return;
  std::string want = "extern model(";
  for (std::size_t i = 0; i < contract->slots.size(); ++i) want += (i ? ", " : "") + slot_text(contract->slots[i]);
  want += ")";
  std::vector<bool> used(contract->slots.size(), false);
  std::vector<const ast::ModelVar*> extra;
  for (const ast::ModelVar& v : model->vars) {
    bool matched = false;
    for (std::size_t i = 0; i < contract->slots.size() && !matched; ++i) {
      if (!used[i] && fits(contract->slots[i], v, ctx.symbols)) used[i] = matched = true;
    }
    if (!matched) extra.push_back(&v);
  }
  for (const ast::ModelVar* v : extra) {
    ctx.diags.error(v->loc, "model variable '" + v->name.name + "' (" + var_text(*v) +
                                ") is not part of the kit's model; the kit runs " + want);
  }
  for (std::size_t i = 0; i < contract->slots.size(); ++i) {
    if (used[i]) continue;
    ctx.diags.error(model_loc, "model '" + model->name.name + "' has no variable of '" + slot_text(contract->slots[i]) +
                                   "'; the kit runs " + want);
  }
}

}  // namespace ksmc::compiler::check
