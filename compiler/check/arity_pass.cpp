#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

namespace {

std::string plural(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

void check_atom(Context& ctx, const ast::Atom& a) {
  const PredicateSym* p = ctx.symbols.predicate(a.pred.name);
  if (p == nullptr) return;  // reported by the names pass
  const auto& params = p->decl->args;
  if (a.args.size() != params.size()) {
    ctx.diags.error(a.pred.loc, "predicate '" + a.pred.name + "' takes " + plural(params.size(), "argument") +
                                    ", but " + std::to_string(a.args.size()) + " " +
                                    (a.args.size() == 1 ? "was" : "were") + " given");
    return;
  }
  for (std::size_t i = 0; i < params.size(); ++i) {
    auto c = ctx.symbols.constants.find(a.args[i].name);
    if (c == ctx.symbols.constants.end()) continue;  // a variable
    if (c->second.type != params[i].type.name) {
      ctx.diags.error(a.args[i].loc, "argument " + std::to_string(i + 1) + " of '" + a.pred.name + "' must be of type '" +
                                         params[i].type.name + "', but constant '" + a.args[i].name + "' is of type '" +
                                         c->second.type + "'");
    }
  }
}

bool same_args(const ast::Atom& a, const ast::Atom& b) {
  if (a.args.size() != b.args.size()) return false;
  for (std::size_t i = 0; i < a.args.size(); ++i) {
    if (a.args[i].name != b.args[i].name) return false;
  }
  return true;
}

}  // namespace

void ArityPass::run(Context& ctx) {
  for (const ast::Module& m : ctx.program.modules) {
    for (const Scope& scope : collect_scopes(m)) {
      for (const ast::Atom* a : scope.atoms) check_atom(ctx, *a);
    }
    for (const ast::Item& item : m.items) {
      const auto* r = std::get_if<ast::Rule>(&item.node);
      if (r == nullptr || !r->exactly_one) continue;
      for (const ast::Atom& alt : r->alternatives) {
        if (!same_args(alt, r->alternatives.front())) {
          ctx.diags.error(alt.pred.loc, "the alternatives of 'exactly one of' must have the same arguments");
          break;
        }
      }
    }
  }
}

}  // namespace ksmc::compiler::check
