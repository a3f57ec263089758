#include <map>

#include "compiler/check/passes.h"

namespace ksmc::compiler::check {

void ExtractPass::run(Context& ctx) {
  std::map<std::string, ast::Loc> seen;
  for (const ast::Module& m : ctx.program.modules) {
    for (const ast::Item& item : m.items) {
      const auto* e = std::get_if<ast::ExtractDecl>(&item.node);
      if (e == nullptr) continue;
      const ast::Atom& t = e->target;
      const PredicateSym* p = ctx.symbols.predicate(t.pred.name);
      if (p != nullptr && p->query) {
        ctx.diags.error(t.pred.loc, "'" + t.pred.name + "' is a query predicate; only evidence predicates are extracted");
      }
      auto [it, inserted] = seen.emplace(t.pred.name, t.pred.loc);
      if (!inserted) {
        ctx.diags.error(t.pred.loc, "evidence '" + t.pred.name + "' already has an extractor (at " + ctx.where(it->second) + ")");
      }
      for (std::size_t i = 0; i < t.args.size(); ++i) {
        if (ctx.symbols.constants.count(t.args[i].name) != 0) {
          ctx.diags.error(t.args[i].loc, "the arguments of an extracted atom must be variables; '" + t.args[i].name +
                                             "' is a constant");
        }
        for (std::size_t j = 0; j < i; ++j) {
          if (t.args[j].name == t.args[i].name) {
            ctx.diags.error(t.args[i].loc, "variable '" + t.args[i].name + "' appears twice in the extracted atom");
          }
        }
      }
    }
  }
}

}  // namespace ksmc::compiler::check
