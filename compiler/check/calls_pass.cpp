#include <map>
#include <set>

#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

namespace {

// The type of an argument expression. `base` is empty when unknown (an error was already
// reported), which then matches anything to avoid cascades.
struct ArgType {
  std::string base;  // int, real, a quantity, string, bool, a domain/value type, query, evidence
  int list = 0;
  bool set = false;
  std::string unit;  // for quantities: the unit written
};

std::string article(const std::string& w) {
  return (!w.empty() && std::string("aeiouAEIOU").find(w[0]) != std::string::npos) ? "an " : "a ";
}

// "a length (mm)", "an angle (rad, deg)", "a value in pixels (px)" (plural quantity names).
std::string quantity_phrase(const std::string& name, const std::string& units) {
  const std::string head = (!name.empty() && name.back() == 's') ? "a value in " + name : article(name) + name;
  return units.empty() ? head : head + " (" + units + ")";
}

class Checker {
 public:
  explicit Checker(Context& ctx) : ctx_(ctx), s_(ctx.symbols) {}

  void scope(const Scope& sc) {
    vars_.clear();
    for (const auto& [name, vt] : infer_variable_types(sc, s_)) vars_[name] = vt.type;
    const std::string kind = sc.kind == Scope::Kind::Extract ? "extractor"
                             : sc.kind == Scope::Kind::Kernel ? "proposal"
                             : sc.kind == Scope::Kind::Output ? "output"
                             : std::holds_alternative<ast::LikelihoodDecl>(sc.item->node) ? "likelihood"
                                                                                           : "prior";
    for (const ast::Call* c : sc.calls) {
      const ArgType result = call(*c, kind);
      if (kind == "extractor" && !result.base.empty() && (result.base != "bool" || result.list != 0)) {
        ctx_.diags.error(c->loc, "extractor '" + c->name + "' must return bool, but returns " + describe(result));
      }
    }
    if (const auto* p = std::get_if<ast::PriorDecl>(&sc.item->node)) conditions(*p);
  }

  void extern_defaults(const ast::ExternDecl& x) {
    vars_.clear();
    for (const ast::Param& p : x.params) {
      if (!p.default_value) continue;
      const ArgType t = expr(*p.default_value);
      const std::string err = mismatch(p.type, t);
      if (!err.empty()) ctx_.diags.error(p.default_value->loc, "default of parameter '" + p.name.name + "' " + err);
    }
  }

 private:
  std::string describe(const ArgType& t) const {
    if (t.set) return "a set";
    if (t.list > 0) return "a list";
    if (t.base == "int" || t.base == "real") return "a number without unit";
    if (t.base == "string") return "a string";
    if (t.base == "bool") return "a boolean";
    if (t.base == "query") return "a query predicate name";
    if (t.base == "evidence") return "an evidence predicate name";
    const TypeSym* ts = s_.type(t.base);
    if (ts != nullptr && ts->kind == TypeSym::Kind::Quantity) return quantity_phrase(t.base, t.unit);
    if (ts != nullptr && ts->kind == TypeSym::Kind::Domain) return "a variable of type '" + t.base + "'";
    return "a value of type '" + t.base + "'";
  }

  std::string expected(const ast::TypeRef& p) const {
    if (p.is_set) {
      if (p.name == "pred") return "a set of predicate names";
      if (p.name == "label") return "a set of label predicate names";
      return "a set of " + p.name + " predicate names";
    }
    if (p.name == "query" || p.name == "evidence") return "a " + p.name + " predicate name";
    if (p.name == "pred") return "a predicate name";
    if (p.list_depth > 0) {
      std::string s = p.name;
      for (int i = 0; i < p.list_depth; ++i) s += "[]";
      return "a list '" + s + "'";
    }
    const TypeSym* ts = s_.type(p.name);
    if (ts != nullptr && ts->kind == TypeSym::Kind::Quantity) {
      std::string units;
      for (const ast::UnitDef& u : ts->quantity->units) units += (units.empty() ? "" : ", ") + u.name.name;
      return quantity_phrase(p.name, units);
    }
    if (p.name == "entity") return "a variable of a domain type";
    if (ts != nullptr && ts->kind == TypeSym::Kind::Domain) return "a variable of type '" + p.name + "'";
    if (p.name == "real") return "a number";
    if (p.name == "int") return "an integer";
    if (p.name == "bool") return "a boolean (true or false)";
    if (p.name == "string") return "a string";
    return "a value of type '" + p.name + "'";
  }

  bool base_ok(const std::string& want, const ArgType& got) const {
    if (got.base.empty() || want == got.base) return true;
    if (want == "real" && got.base == "int") return true;
    if (want == "entity") return s_.is_domain_type(got.base);
    if (want == "pred" || want == "label") return got.base == "query" || got.base == "evidence";
    return false;
  }

  // "" when `got` fits parameter type `p`, else "expects X, got Y".
  std::string mismatch(const ast::TypeRef& p, const ArgType& got) const {
    if (got.base.empty()) return "";
    bool ok = false;
    if (p.is_set) {
      ok = got.set && base_ok(p.name, got);
    } else {
      ok = !got.set && got.list == p.list_depth && base_ok(p.name, got);
    }
    return ok ? "" : "expects " + expected(p) + ", got " + describe(got);
  }

  ArgType number(const ast::Number& n) {
    if (n.unit.empty()) return ArgType{n.integral ? "int" : "real", 0, false, ""};
    auto u = s_.units.find(n.unit);
    if (u == s_.units.end()) {
      std::string msg = "unknown unit '" + n.unit + "'";
      if (s_.units.empty()) msg += " (units are declared by 'quantity' in stdlib/core.ksm; include it)";
      ctx_.diags.error(n.unit_loc, msg);
      return {};
    }
    return ArgType{u->second.quantity, 0, false, n.unit};
  }

  ArgType unify(const std::vector<ast::Expr>& items, bool set) {
    ArgType out;
    out.set = set;
    bool first = true;
    for (const ast::Expr& e : items) {
      ArgType t = expr(e);
      if (t.base.empty()) return {};
      if (first) {
        out.base = t.base;
        out.list = t.list;
        out.unit = t.unit;
        first = false;
        continue;
      }
      if ((out.base == "int" && t.base == "real") || (out.base == "real" && t.base == "int")) {
        out.base = "real";
      } else if (t.base != out.base || t.list != out.list) {
        ctx_.diags.error(e.loc, std::string("elements of a ") + (set ? "set" : "list") + " must have one type; this is " +
                                    describe(t) + ", the first is " + describe(out));
        return {};
      }
    }
    if (first) return {};  // empty: fits any list / set
    if (!set) out.list += 1;
    return out;
  }

  ArgType expr(const ast::Expr& e) {
    switch (e.kind) {
      case ast::Expr::Kind::Number: return number(e.number);
      case ast::Expr::Kind::String: return ArgType{"string", 0, false, ""};
      case ast::Expr::Kind::Bool: return ArgType{"bool", 0, false, ""};
      case ast::Expr::Kind::Inf: return ArgType{"real", 0, false, ""};
      case ast::Expr::Kind::List: return unify(e.items, false);
      case ast::Expr::Kind::Set: return unify(e.items, true);
      case ast::Expr::Kind::Call: return call(*e.call, "function");
      case ast::Expr::Kind::Index: return index(e);
      case ast::Expr::Kind::Name: return name(e);
    }
    return {};
  }

  ArgType index(const ast::Expr& e) {
    auto mv = s_.model_vars.find(e.text);
    if (mv == s_.model_vars.end()) {
      ctx_.diags.error(e.loc, "unknown model variable '" + e.text + "'");
      return {};
    }
    if (!mv->second.decl->collection) {
      ctx_.diags.error(e.loc, "model variable '" + e.text + "' is not indexed");
      return {};
    }
    auto v = vars_.find(e.index.name);
    if (v == vars_.end()) {
      ctx_.diags.error(e.index.loc, "unknown variable '" + e.index.name + "' (not used in this declaration's atoms)");
    } else if (!mv->second.element_type.empty() && !v->second.empty() && v->second != mv->second.element_type) {
      ctx_.diags.error(e.index.loc, "'" + e.text + "' is indexed by '" + mv->second.element_type + "', but '" + e.index.name +
                                        "' is of type '" + v->second + "'");
    }
    const ast::TypeRef& t = mv->second.decl->type;
    return ArgType{t.name, t.list_depth, false, ""};
  }

  ArgType name(const ast::Expr& e) {
    if (auto v = vars_.find(e.text); v != vars_.end()) return ArgType{v->second, 0, false, ""};
    if (auto mv = s_.model_vars.find(e.text); mv != s_.model_vars.end()) {
      const ast::TypeRef& t = mv->second.decl->type;
      return ArgType{t.name, t.list_depth + (mv->second.decl->collection ? 1 : 0), false, ""};
    }
    if (const PredicateSym* p = s_.predicate(e.text)) return ArgType{p->query ? "query" : "evidence", 0, false, ""};
    if (auto c = s_.constants.find(e.text); c != s_.constants.end()) return ArgType{c->second.type, 0, false, ""};
    ctx_.diags.error(e.loc, "unknown name '" + e.text + "'");
    return {};
  }

  ArgType call(const ast::Call& c, const std::string& kind) {
    auto it = s_.externs.find(c.name);
    if (it == s_.externs.end() || it->second.decl->kind.name != kind) {
      if (it != s_.externs.end()) {
        ctx_.diags.error(c.loc, "'" + c.name + "' is " + article(it->second.decl->kind.name) + it->second.decl->kind.name +
                                    ", not " + article(kind) + kind);
      } else {
        std::vector<std::string> same_kind;
        for (const auto& [n, x] : s_.externs) {
          if (x.decl->kind.name == kind) same_kind.push_back(n);
        }
        std::string msg = "unknown " + kind + " '" + c.name + "'";
        const std::string hint = suggest(c.name, same_kind);
        if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
        ctx_.diags.error(c.loc, msg);
      }
      for (const ast::Arg& a : c.args) expr(a.value);  // still check the arguments' own names
      return {};
    }
    const ast::ExternDecl& x = *it->second.decl;
    std::vector<const ast::Arg*> given(x.params.size(), nullptr);
    std::size_t positional = 0;
    bool named_seen = false;
    for (const ast::Arg& a : c.args) {
      const ArgType t = expr(a.value);
      std::size_t slot = x.params.size();
      if (!a.name) {
        if (named_seen) {
          ctx_.diags.error(a.value.loc, "positional argument after a named one");
          continue;
        }
        if (positional >= x.params.size()) {
          ctx_.diags.error(a.value.loc, "too many arguments to '" + c.name + "' (it takes " +
                                            std::to_string(x.params.size()) + ")");
          continue;
        }
        slot = positional++;
      } else {
        named_seen = true;
        for (std::size_t i = 0; i < x.params.size(); ++i) {
          if (x.params[i].name.name == a.name->name) slot = i;
        }
        if (slot == x.params.size()) {
          std::vector<std::string> names;
          for (const ast::Param& p : x.params) names.push_back(p.name.name);
          std::string msg = "unknown parameter '" + a.name->name + "' of '" + c.name + "'";
          const std::string hint = suggest(a.name->name, names);
          if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
          ctx_.diags.error(a.name->loc, msg);
          continue;
        }
        if (given[slot] != nullptr) {
          ctx_.diags.error(a.name->loc, "parameter '" + a.name->name + "' of '" + c.name + "' is given twice");
          continue;
        }
      }
      given[slot] = &a;
      const std::string err = mismatch(x.params[slot].type, t);
      if (!err.empty()) {
        ctx_.diags.error(a.value.loc, "parameter '" + x.params[slot].name.name + "' of '" + c.name + "' " + err);
      }
    }
    for (std::size_t i = 0; i < x.params.size(); ++i) {
      if (given[i] == nullptr && !x.params[i].default_value) {
        ctx_.diags.error(c.loc, "missing argument for parameter '" + x.params[i].name.name + "' of '" + c.name + "'");
      }
    }
    if (!x.result) {
      if (kind == "function") ctx_.diags.error(c.loc, "function '" + c.name + "' returns nothing");
      return kind == "function" ? ArgType{} : ArgType{};
    }
    return ArgType{x.result->name, x.result->list_depth, x.result->is_set, ""};
  }

  void conditions(const ast::PriorDecl& p) {
    for (const ast::Condition& c : p.conditions) {
      const PredicateSym* ps = s_.predicate(c.atom.pred.name);
      if (!c.is_prob) continue;
      if (ps != nullptr && !ps->query) {
        ctx_.diags.error(c.atom.pred.loc, "P(...) needs a query predicate; '" + c.atom.pred.name + "' is evidence");
      }
      if (!c.threshold.unit.empty()) ctx_.diags.error(c.threshold.unit_loc, "a probability threshold has no unit");
      if (c.threshold.value < 0.0 || c.threshold.value > 1.0) {
        ctx_.diags.error(c.threshold.loc, "probability threshold " + c.threshold.text + " is outside [0, 1]");
      }
    }
  }

  Context& ctx_;
  const SymbolTable& s_;
  std::map<std::string, std::string> vars_;
};

}  // namespace

void CallsPass::run(Context& ctx) {
  Checker checker(ctx);
  for (const ast::Module& m : ctx.program.modules) {
    for (const Scope& sc : collect_scopes(m)) checker.scope(sc);
    for (const ast::Item& item : m.items) {
      if (const auto* x = std::get_if<ast::ExternDecl>(&item.node)) checker.extern_defaults(*x);
    }
  }
}

}  // namespace ksmc::compiler::check
