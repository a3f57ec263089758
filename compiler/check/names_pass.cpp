#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

namespace {

std::vector<std::string> keys_of(const auto& map) {
  std::vector<std::string> out;
  for (const auto& [k, v] : map) out.push_back(k);
  return out;
}

class Names {
 public:
  explicit Names(Context& ctx) : ctx_(ctx), s_(ctx.symbols) {}

  void type(const std::string& name, const ast::Loc& loc, bool domain_only) {
    const TypeSym* t = s_.type(name);
    // Built in: set<pred>, set<label>, and single-predicate parameters query / evidence / pred.
    if (t == nullptr && (name == "pred" || name == "label" || name == "query" || name == "evidence")) return;
    if (t == nullptr) {
      std::string msg = "undeclared type '" + name + "'";
      const std::string hint = suggest(name, keys_of(s_.types));
      if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
      ctx_.diags.error(loc, msg);
    } else if (domain_only && t->kind != TypeSym::Kind::Domain) {
      ctx_.diags.error(loc, "'" + name + "' is not a domain type (declare it with 'type " + name + ";')");
    }
  }

  void type_ref(const ast::TypeRef& t) {
    if (t.is_set) {
      if (t.name != "query" && t.name != "evidence" && t.name != "pred" && t.name != "label") type(t.name, t.loc, true);
      return;
    }
    type(t.name, t.loc, false);
  }

  void predicate(const ast::Ident& p) {
    if (s_.predicate(p.name) != nullptr) return;
    std::string msg = "undeclared predicate '" + p.name + "'";
    const std::string hint = suggest(p.name, keys_of(s_.predicates));
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    ctx_.diags.error(p.loc, msg);
  }

  void kernel(const ast::Ident& k) {
    if (s_.kernels.count(k.name) != 0) return;
    std::string msg = "undeclared kernel '" + k.name + "'";
    const std::string hint = suggest(k.name, keys_of(s_.kernels));
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    ctx_.diags.error(k.loc, msg);
  }

  void item(const ast::Item& item) {
    if (const auto* d = std::get_if<ast::PredDecl>(&item.node)) {
      for (const ast::PredSig& p : d->preds) {
        for (const ast::PredArg& a : p.args) type(a.type.name, a.type.loc, true);
      }
    } else if (const auto* x = std::get_if<ast::ExternDecl>(&item.node)) {
      for (const ast::Param& p : x->params) type_ref(p.type);
      if (x->result) type_ref(*x->result);
      if (x->reads) type_ref(*x->reads);
    } else if (const auto* mc = std::get_if<ast::ModelContractDecl>(&item.node)) {
      for (const ast::ModelSlot& s : mc->slots) {
        type(s.type.name, s.type.loc, false);
        if (s.index && s.index->name != "entity") type(s.index->name, s.index->loc, true);
      }
    } else if (const auto* m = std::get_if<ast::ModelDecl>(&item.node)) {
      for (const ast::ModelVar& v : m->vars) {
        if (v.index) type(v.index->name, v.index->loc, true);
        type_ref(v.type);
      }
    } else if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) {
      for (const ast::KernelParam& p : k->params) type(p.type.name, p.type.loc, true);
    } else if (const auto* s = std::get_if<ast::ScheduleDecl>(&item.node)) {
      for (const ast::ScheduleRow& row : s->rows) {
        for (const ast::ScheduleEntry& e : row.entries) kernel(e.kernel);
      }
    } else if (const auto* p = std::get_if<ast::PriorDecl>(&item.node)) {
      for (const ast::Condition& c : p->conditions) {
        if (c.is_prob && c.fn.name != "P") {
          ctx_.diags.error(c.fn.loc, "unknown condition '" + c.fn.name + "(...)'; write P(atom) > threshold");
        }
      }
    }
  }

 private:
  Context& ctx_;
  const SymbolTable& s_;
};

}  // namespace

void NamesPass::run(Context& ctx) {
  Names names(ctx);
  for (const ast::Module& m : ctx.program.modules) {
    for (const ast::Item& item : m.items) names.item(item);
    for (const Scope& scope : collect_scopes(m)) {
      for (const ast::Atom* a : scope.atoms) names.predicate(a->pred);
    }
  }
}

}  // namespace ksmc::compiler::check
