#include "compiler/check/passes.h"

namespace ksmc::compiler::check {

void KernelsPass::run(Context& ctx) {
  const auto& kernels = ctx.symbols.kernels;
  for (const auto& [name, k] : kernels) {
    if (!k.reverse) {
      ctx.diags.error(k.name.loc, "kernel '" + name + "' has no reverse: add 'reverse NAME' ('reverse " + name +
                                      "' if it is its own reverse) or declare it as 'kernel pair " + name + " / NAME'");
      continue;
    }
    if (!k.decl->pair && k.reverse->name != name) {  // a kernel and its reverse are declared together
      ctx.diags.error(k.reverse->loc, "kernel '" + name + "' names another kernel '" + k.reverse->name +
                                          "' as its reverse; declare the two together: 'kernel pair " + name + " / " +
                                          k.reverse->name + " = ...;'");
      continue;
    }
    auto r = kernels.find(k.reverse->name);
    if (r == kernels.end()) {
      ctx.diags.error(k.reverse->loc, "reverse kernel '" + k.reverse->name + "' of '" + name + "' is not declared");
      continue;
    }
    if (r->second.reverse && r->second.reverse->name != name) {
      ctx.diags.error(k.reverse->loc, "kernel '" + name + "' names '" + k.reverse->name + "' as its reverse, but '" +
                                          k.reverse->name + "' names '" + r->second.reverse->name + "'");
    }
  }
}

}  // namespace ksmc::compiler::check
