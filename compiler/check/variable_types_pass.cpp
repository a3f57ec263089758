#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

void VariableTypesPass::run(Context& ctx) {
  for (const ast::Module& m : ctx.program.modules) {
    for (const Scope& scope : collect_scopes(m)) {
      const auto types = infer_variable_types(
          scope, ctx.symbols, [&](const std::string& var, const VarType& first, const std::string& type, const ast::Loc& loc) {
            ctx.diags.error(loc, "variable '" + var + "' is used as '" + type + "' here but as '" + first.type + "' at " +
                                     ctx.where(first.loc));
          });
      // `for` / `exists` variables must occur in an atom, or they have no type.
      for (const ast::Ident* b : scope.binders) {
        auto it = types.find(b->name);
        if (it == types.end()) {
          ctx.diags.error(b->loc, scope.kind == Scope::Kind::Prior
                                      ? "variable '" + b->name + "' of the prior is not typed by any where-condition"
                                      : "variable '" + b->name + "' is bound by 'exists' but never used");
        }
      }
    }
  }
}

}  // namespace ksmc::compiler::check
