// The parameter half of the kit contract: ranges (after unit conversion), fixed list
// shapes, row sums and label sets, for every call argument and every signature default.
#include <cmath>
#include <set>
#include <sstream>

#include "compiler/check/call_binding.h"
#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"
#include "compiler/fmt/printer.h"

namespace ksmc::compiler::check {
namespace {

bool numeric(const SymbolTable& s, const ast::TypeRef& t) {
  if (t.is_set) return false;
  if (t.name == "real" || t.name == "int") return true;
  const TypeSym* ts = s.type(t.name);
  return ts != nullptr && ts->kind == TypeSym::Kind::Quantity;
}

std::string range_text(const ast::Range& r) {
  auto bound = [](const ast::Bound& b) { return b.inf ? std::string(b.negative ? "-inf" : "inf") : fmt::print_number(b.number); };
  return std::string(r.lo_open ? "(" : "[") + bound(r.lo) + ", " + bound(r.hi) + (r.hi_open ? ")" : "]");
}

class ParamChecker {
 public:
  explicit ParamChecker(Context& ctx) : ctx_(ctx), s_(ctx.symbols) {
    const std::string ct = constant_type(ctx.main(), s_);
    for (const ast::Item& item : ctx.main().items) {
      const auto* r = std::get_if<ast::Rule>(&item.node);
      if (r == nullptr || !r->exactly_one) continue;
      std::vector<std::string> members;
      bool unary = true;
      for (const ast::Atom& a : r->alternatives) {
        const PredicateSym* p = s_.predicate(a.pred.name);
        if (p == nullptr || p->decl->args.size() != 1 || (!ct.empty() && p->decl->args[0].type.name != ct)) unary = false;
        members.push_back(a.pred.name);
      }
      if (!unary) continue;
      for (const std::string& m : members) labels_.insert(m);
      if (label_list_.empty()) {
        for (std::size_t i = 0; i < members.size(); ++i) label_list_ += (i ? ", " : "") + members[i];
      }
    }
    constant_type_ = ct;
  }

  void signature(const ast::ExternDecl& x) {
    for (const ast::Param& p : x.params) {
      if (p.range) {
        if (!numeric(s_, p.type)) {
          ctx_.diags.error(p.range->loc, "a range needs a numeric parameter; '" + p.name.name + "' is " + fmt::print_type(p.type));
        } else {
          bound_unit(p, p.range->lo);
          bound_unit(p, p.range->hi);
          const double lo = bound_value(p.range->lo), hi = bound_value(p.range->hi);
          if (lo > hi) ctx_.diags.error(p.range->loc, "empty range " + range_text(*p.range) + ": the lower bound is above the upper");
        }
      }
      if (p.rowsum && (p.type.is_set || p.type.list_depth == 0 || !numeric(s_, ast::TypeRef{p.type.name, 0, {}, false, {}}))) {
        ctx_.diags.error(p.rowsum_loc, "'rowsum' needs a numeric list or table parameter; '" + p.name.name + "' is " +
                                           fmt::print_type(p.type));
      }
      if (p.default_value) value(p, *p.default_value, "default of parameter '" + p.name.name + "'");
    }
    if (x.reads && (x.reads->list_depth != 1 || x.reads->is_set)) {
      ctx_.diags.error(x.reads->loc, "'reads' names a model collection type such as 'rect[]'");
    }
    if (x.moves.kind == ast::MoveSpec::Kind::Makes && x.kind.name != "proposal") {
      ctx_.diags.error(x.moves.loc, "only a proposal makes or serves moves");
    }
  }

  void call(const ast::Call& c) {
    auto it = s_.externs.find(c.name);
    if (it == s_.externs.end()) return;
    for (const BoundArg& b : bind_call(c, *it->second.decl)) {
      if (b.value == nullptr) continue;
      if (b.value->kind == ast::Expr::Kind::Call) call(*b.value->call);
      if (!b.defaulted) value(*b.param, *b.value, "parameter '" + b.param->name.name + "' of '" + c.name + "'");
      if (it->second.decl->kind.name == "output") per_constant(*b.param, *b.value, c.name);
    }
  }

 private:
  void bound_unit(const ast::Param& p, const ast::Bound& b) {
    if (b.inf || b.number.unit.empty()) return;
    auto u = s_.units.find(b.number.unit);
    if (u == s_.units.end()) {
      ctx_.diags.error(b.number.unit_loc, "unknown unit '" + b.number.unit + "'");
    } else if (u->second.quantity != p.type.name) {
      ctx_.diags.error(b.number.unit_loc, "bound in '" + b.number.unit + "' (" + u->second.quantity + ") for '" + p.name.name +
                                              "', which is " + fmt::print_type(p.type));
    }
  }

  double bound_value(const ast::Bound& b) const {
    if (b.inf) return b.negative ? -INFINITY : INFINITY;
    return base_value(s_, b.number);
  }

  bool inside(const ast::Range& r, double v) const {
    const double lo = bound_value(r.lo), hi = bound_value(r.hi);
    if (std::isnan(v)) return false;
    if (r.lo_open ? !(v > lo) : !(v >= lo)) return false;
    if (r.hi_open ? !(v < hi) : !(v <= hi)) return false;
    return true;
  }

  // Checks `e` (a value for parameter `p`, described by `what`) against p's contract.
  void value(const ast::Param& p, const ast::Expr& e, const std::string& what) {
    if (p.type.is_set && p.type.name == "label" && e.kind == ast::Expr::Kind::Set) labels(p, e, what);
    if (p.type.list_depth > 0 && !p.type.is_set) {
      if (!shape(p, e, 0, what)) return;
    }
    if (p.range) elements(p, e, what);
    if (p.rowsum && e.kind == ast::Expr::Kind::List) rowsums(p, e, what);
  }

  bool shape(const ast::Param& p, const ast::Expr& e, std::size_t depth, const std::string& what) {
    if (e.kind != ast::Expr::Kind::List || depth >= p.type.dims.size()) return true;  // the calls pass checks kinds
    const int want = p.type.dims[depth];
    if (want > 0 && static_cast<int>(e.items.size()) != want) {
      ctx_.diags.error(e.loc, what + " is " + fmt::print_type(p.type) + ": this list has " + std::to_string(e.items.size()) +
                                  " item" + (e.items.size() == 1 ? "" : "s") + ", not " + std::to_string(want));
      return false;
    }
    for (const ast::Expr& item : e.items)
      if (!shape(p, item, depth + 1, what)) return false;
    return true;
  }

  void elements(const ast::Param& p, const ast::Expr& e, const std::string& what) {
    if (e.kind == ast::Expr::Kind::List) {
      for (const ast::Expr& item : e.items) elements(p, item, what);
      return;
    }
    double v = 0.0;
    std::string written;
    if (e.kind == ast::Expr::Kind::Number) {
      if (!e.number.unit.empty() && s_.units.count(e.number.unit) == 0) return;  // the calls pass reported it
      v = base_value(s_, e.number);
      written = fmt::print_number(e.number);
    } else if (e.kind == ast::Expr::Kind::Inf) {
      v = INFINITY;
      written = "inf";
    } else {
      return;
    }
    if (!inside(*p.range, v)) ctx_.diags.error(e.loc, what + " must be in " + range_text(*p.range) + "; " + written + " is not");
  }

  void rowsums(const ast::Param& p, const ast::Expr& e, const std::string& what) {
    const double want = base_value(s_, *p.rowsum);
    auto sum_of = [&](const ast::Expr& row, double& sum) {
      sum = 0.0;
      for (const ast::Expr& x : row.items) {
        if (x.kind != ast::Expr::Kind::Number) return false;
        sum += base_value(s_, x.number);
      }
      return true;
    };
    const bool table = p.type.list_depth >= 2;
    std::vector<const ast::Expr*> rows;
    if (table) {
      for (const ast::Expr& r : e.items)
        if (r.kind == ast::Expr::Kind::List) rows.push_back(&r);
    } else {
      rows.push_back(&e);
    }
    for (std::size_t i = 0; i < rows.size(); ++i) {
      double sum = 0.0;
      if (!sum_of(*rows[i], sum) || std::fabs(sum - want) <= 1e-9) continue;
      std::ostringstream msg;
      msg.precision(12);
      msg << what << ": " << (table ? "row " + std::to_string(i + 1) + " sums" : std::string("the list sums")) << " to " << sum
          << ", not " << fmt::print_number(*p.rowsum) << " (rowsum " << fmt::print_number(*p.rowsum) << ")";
      ctx_.diags.error(rows[i]->loc, msg.str());
    }
  }

  // An output reports a value per constant of the kit's constant type: a predicate it names
  // (`false_est: query`) must be unary over that type.
  void per_constant(const ast::Param& p, const ast::Expr& e, const std::string& block) {
    const std::string& t = p.type.name;
    if (p.type.is_set || p.type.list_depth != 0 || (t != "query" && t != "evidence" && t != "pred")) return;
    if (e.kind != ast::Expr::Kind::Name) return;
    const PredicateSym* pred = s_.predicate(e.text);
    if (pred == nullptr) return;  // the calls pass reported it
    const auto& args = pred->decl->args;
    if (args.size() == 1 && (constant_type_.empty() || args[0].type.name == constant_type_)) return;
    ctx_.diags.error(e.loc, "parameter '" + p.name.name + "' of '" + block + "' reports one value per " +
                                (constant_type_.empty() ? std::string("constant") : "'" + constant_type_ + "'") + ": '" +
                                e.text + "' must be a unary predicate over " +
                                (constant_type_.empty() ? std::string("the kit's constant type") : "'" + constant_type_ + "'"));
  }

  void labels(const ast::Param& p, const ast::Expr& e, const std::string& what) {
    (void)p;
    for (const ast::Expr& item : e.items) {
      if (item.kind != ast::Expr::Kind::Name || labels_.count(item.text) != 0) continue;
      if (s_.predicate(item.text) == nullptr) continue;  // the calls pass reported it
      std::string msg = what + ": '" + item.text + "' is not a label; labels are the members of an 'exactly one of' block";
      msg += constant_type_.empty() ? std::string(" over one type") : " over '" + constant_type_ + "'";
      msg += label_list_.empty() ? std::string(" (the domain declares none)") : " (" + label_list_ + ")";
      ctx_.diags.error(item.loc, msg);
    }
  }

  Context& ctx_;
  const SymbolTable& s_;
  std::set<std::string> labels_;
  std::string label_list_;
  std::string constant_type_;
};

}  // namespace

void ContractParamsPass::run(Context& ctx) {
  ParamChecker checker(ctx);
  for (const ast::Module& m : ctx.program.modules)
    for (const ast::Item& item : m.items)
      if (const auto* x = std::get_if<ast::ExternDecl>(&item.node)) checker.signature(*x);
  for (const Scope& sc : collect_scopes(ctx.main()))
    for (const ast::Call* c : sc.calls) checker.call(*c);
}

}  // namespace ksmc::compiler::check
