#include <map>

#include "compiler/check/passes.h"
#include "compiler/check/rule_names.h"

namespace ksmc::compiler::check {

void RuleNamesPass::run(Context& ctx) {
  std::map<std::string, ast::Loc> seen;
  for (const ast::Item& item : ctx.main().items) {
    const auto* r = std::get_if<ast::Rule>(&item.node);
    if (r == nullptr) continue;
    const std::string name = rule_name(*r);
    const ast::Loc at = r->label ? r->label->loc : item.loc;
    auto [it, fresh] = seen.emplace(name, at);
    if (!fresh) {
      ctx.diags.error(at, "duplicate rule name '" + name + "' (first used at " + ctx.where(it->second) + ")" +
                              (r->label ? "" : "; the rules have the same formula: name one with '@name'"));
      continue;
    }
    ctx.symbols.rule_names[r] = name;
  }
}

}  // namespace ksmc::compiler::check
