#include <algorithm>

#include "compiler/check/passes.h"

namespace ksmc::compiler::check {

namespace {

class Declarer {
 public:
  explicit Declarer(Context& ctx) : ctx_(ctx), s_(ctx.symbols) {}

  void module(const ast::Module& m, int index) {
    module_ = index;
    for (const ast::Item& item : m.items) std::visit([&](const auto& n) { declare(n, item); }, item.node);
  }

  void finish() {
    // A variable-size collection named like a domain type supplies that type's constants.
    for (auto& [name, mv] : s_.model_vars) {
      if (mv.decl->index) {
        mv.element_type = mv.decl->index->name;
      } else if (mv.decl->collection && s_.is_domain_type(name)) {
        mv.element_type = name;
      }
    }
  }

 private:
  template <typename Map>
  bool fresh(const Map& map, const std::string& what, const ast::Ident& id) {
    auto it = map.find(id.name);
    if (it == map.end()) return true;
    ctx_.diags.error(id.loc, "duplicate " + what + " '" + id.name + "' (first declared at " + ctx_.where(loc_of(it->second)) + ")");
    return false;
  }
  static ast::Loc loc_of(const TypeSym& t) { return t.loc; }
  static ast::Loc loc_of(const PredicateSym& p) { return p.decl->name.loc; }
  static ast::Loc loc_of(const UnitSym& u) { return u.loc; }
  static ast::Loc loc_of(const ConstantSym& c) { return c.loc; }
  static ast::Loc loc_of(const ExternSym& e) { return e.decl->name_loc; }
  static ast::Loc loc_of(const ModelVarSym& m) { return m.decl->name.loc; }
  static ast::Loc loc_of(const KernelSym& k) { return k.name.loc; }

  void declare(const ast::DomainDecl& d, const ast::Item&) {
    if (module_ != 0) return;  // included files' domain names do not matter
    if (!s_.domain.empty()) {
      ctx_.diags.error(d.name.loc, "a file declares one domain; '" + s_.domain + "' was declared before");
      return;
    }
    s_.domain = d.name.name;
  }
  void declare(const ast::IncludeDecl&, const ast::Item&) {}
  void declare(const ast::TypeDecl& t, const ast::Item&) {
    if (fresh(s_.types, "type", t.name)) {
      s_.types[t.name.name] = TypeSym{TypeSym::Kind::Domain, t.name.loc, module_, &t, nullptr};
    }
    for (const ast::Ident& c : t.constants) {
      if (fresh(s_.constants, "constant", c)) s_.constants[c.name] = ConstantSym{t.name.name, c.loc};
    }
  }
  void declare(const ast::PredDecl& d, const ast::Item&) {
    for (const ast::PredSig& p : d.preds) {
      if (fresh(s_.predicates, "predicate", p.name)) s_.predicates[p.name.name] = PredicateSym{&p, d.query, module_};
      const auto excl = std::count_if(p.args.begin(), p.args.end(), [](const ast::PredArg& a) { return a.exclusive; });
      if (excl > 0 && !d.query) {
        ctx_.diags.error(p.name.loc, "'!' (mutually exclusive argument) is only allowed on query predicates");
      }
      if (excl > 0 && static_cast<std::size_t>(excl) == p.args.size()) {
        ctx_.diags.error(p.name.loc, "predicate '" + p.name.name + "' marks every argument with '!'; at least one must stay free");
      }
    }
  }
  void declare(const ast::QuantityDecl& q, const ast::Item&) {
    if (fresh(s_.types, "type", q.name)) {
      s_.types[q.name.name] = TypeSym{TypeSym::Kind::Quantity, q.name.loc, module_, nullptr, &q};
    }
    for (const ast::UnitDef& u : q.units) {
      if (!u.scale.unit.empty()) ctx_.diags.error(u.scale.unit_loc, "the scale of unit '" + u.name.name + "' must be a plain number");
      if (u.scale.value <= 0.0) ctx_.diags.error(u.scale.loc, "the scale of unit '" + u.name.name + "' must be positive");
      if (fresh(s_.units, "unit", u.name)) s_.units[u.name.name] = UnitSym{q.name.name, u.scale.value, u.name.loc};
    }
  }
  void declare(const ast::ValueDecl& v, const ast::Item&) {
    for (const ast::Ident& n : v.names) {
      if (fresh(s_.types, "type", n)) s_.types[n.name] = TypeSym{TypeSym::Kind::Value, n.loc, module_, nullptr, nullptr};
    }
  }
  void declare(const ast::ExternDecl& x, const ast::Item&) {
    const auto& kinds = extern_kinds();
    if (std::find(kinds.begin(), kinds.end(), x.kind.name) == kinds.end()) {
      ctx_.diags.error(x.kind.loc, "unknown extern kind '" + x.kind.name +
                                       "' (expected extractor, prior, likelihood, proposal, function or output)");
    }
    for (std::size_t i = 0; i < x.params.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        if (x.params[j].name.name == x.params[i].name.name) {
          ctx_.diags.error(x.params[i].name.loc, "duplicate parameter '" + x.params[i].name.name + "'");
        }
      }
    }
    ast::Ident id{x.name, x.name_loc};
    if (fresh(s_.externs, "extern", id)) s_.externs[x.name] = ExternSym{&x, module_};
  }
  void declare(const ast::Rule&, const ast::Item&) {}
  void declare(const ast::ModelDecl& m, const ast::Item&) {
    for (const ast::ModelVar& v : m.vars) {
      if (fresh(s_.model_vars, "model variable", v.name)) s_.model_vars[v.name.name] = ModelVarSym{&v, "", module_};
    }
  }
  void declare(const ast::ExtractDecl&, const ast::Item&) {}
  void declare(const ast::PriorDecl&, const ast::Item&) {}
  void declare(const ast::LikelihoodDecl&, const ast::Item&) {}
  void declare(const ast::OutputDecl&, const ast::Item&) {}
  void declare(const ast::ModelContractDecl& d, const ast::Item&) { s_.model_contracts.emplace_back(&d, module_); }
  void declare(const ast::KernelDecl& k, const ast::Item&) {
    if (fresh(s_.kernels, "kernel", k.name)) s_.kernels[k.name.name] = KernelSym{&k, k.name, k.reverse, module_};
    if (k.pair && k.reverse && k.reverse->name != k.name.name) {
      if (fresh(s_.kernels, "kernel", *k.reverse)) s_.kernels[k.reverse->name] = KernelSym{&k, *k.reverse, k.name, module_};
    }
  }
  void declare(const ast::ScheduleDecl& s, const ast::Item& item) {
    if (!s_.schedules.empty()) {
      ctx_.diags.error(item.loc, "only one schedule may be declared");
      return;
    }
    s_.schedules.push_back(&s);
  }

  Context& ctx_;
  SymbolTable& s_;
  int module_ = 0;
};

}  // namespace

void SymbolsPass::run(Context& ctx) {
  Declarer d(ctx);
  // Included files first so that "first declared at" points into the stdlib when a user
  // file redeclares a stdlib name.
  for (std::size_t i = 1; i < ctx.program.modules.size(); ++i) d.module(ctx.program.modules[i], static_cast<int>(i));
  if (!ctx.program.modules.empty()) d.module(ctx.program.modules.front(), 0);
  d.finish();
}

}  // namespace ksmc::compiler::check
