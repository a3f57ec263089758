#include <cctype>

#include "compiler/check/passes.h"
#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

// In rules, an atom argument naming a declared constant is that constant; any other name
// is a variable. A capitalised name that no type declares is almost always meant as a
// constant (Alchemy's convention: `Smokes(Anna)`); taken as a variable it would silently
// quantify the rule over every person. So it is an error.
void RuleConstantsPass::run(Context& ctx) {
  std::vector<std::string> declared;
  for (const auto& [name, c] : ctx.symbols.constants) declared.push_back(name);
  for (const ast::Module& m : ctx.program.modules) {
    for (const Scope& scope : collect_scopes(m)) {
      if (scope.kind != Scope::Kind::Rule) continue;
      for (const ast::Atom* atom : scope.atoms) {
        for (const ast::Ident& arg : atom->args) {
          if (arg.name.empty() || !std::isupper(static_cast<unsigned char>(arg.name.front()))) continue;
          if (ctx.symbols.constants.count(arg.name) > 0) continue;
          std::string msg = "'" + arg.name + "' in '" + atom->pred.name +
                            "' is capitalised like a constant, but no type declares it; declare it in an "
                            "enumerated type (type t = {" + arg.name + ", ...};) or write a lowercase variable";
          const std::string near = suggest(arg.name, declared);
          if (!near.empty()) msg += " (did you mean '" + near + "'?)";
          ctx.diags.error(arg.loc, msg);
        }
      }
    }
  }
}

}  // namespace ksmc::compiler::check
