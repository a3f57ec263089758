#include <map>
#include <set>

#include "compiler/check/passes.h"
#include "compiler/check/rule_names.h"

namespace ksmc::compiler::check {

void RuleNamesPass::run(Context& ctx) {
  // Unnamed rules whose short names collide although their formulas differ take the long
  // (8-digit) hash: a collision of 16-bit hashes is not the user's mistake.
  std::map<std::string, std::set<std::string>> formulas_by_name;
  for (const ast::Item& item : ctx.main().items)
    if (const auto* r = std::get_if<ast::Rule>(&item.node); r != nullptr && !r->label)
      formulas_by_name[rule_name(*r)].insert(normalized_rule_text(*r));
  std::map<std::string, ast::Loc> seen;
  for (const ast::Item& item : ctx.main().items) {
    const auto* r = std::get_if<ast::Rule>(&item.node);
    if (r == nullptr) continue;
    std::string name = rule_name(*r);
    if (!r->label && formulas_by_name[name].size() > 1) name = rule_name(*r, true);
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
