#include "compiler/check/passes.h"

namespace ksmc::compiler::check {

void WeightsPass::run(Context& ctx) {
  for (const ast::Module& m : ctx.program.modules) {
    for (const ast::Item& item : m.items) {
      const auto* r = std::get_if<ast::Rule>(&item.node);
      if (r == nullptr) continue;
      const ast::Number* w = r->prob ? &*r->prob : (r->weight ? &*r->weight : nullptr);
      if (r->hard && w != nullptr) {
        ctx.diags.error(w->loc, "a hard rule cannot have a weight (remove 'hard' or the weight)");
        continue;
      }
      if (!r->hard && w == nullptr) {
        ctx.diags.error(r->head_loc, "rule has no weight: start it with 'hard', 'prob p:' or 'w x:'");
        continue;
      }
      if (w != nullptr && !w->unit.empty()) {
        ctx.diags.error(w->unit_loc, "a rule weight has no unit");
      }
      if (r->prob && !(r->prob->value > 0.0 && r->prob->value < 1.0)) {
        ctx.diags.error(r->prob->loc, "probability " + r->prob->text +
                                          " is outside (0, 1); use 'hard' for certain rules or 'w x:' for raw weights");
      }
    }
  }
}

}  // namespace ksmc::compiler::check
