// The sampler items of a domain fit the kit: at least one likelihood (when the domain has a
// model); several are factors of one likelihood (the data of several sensors), each block
// at most once and all declared by one kit; `prior for ...:` terms are per-binding priors
// (`-> real`), plain `prior` items are global terms (no result), and each output block is
// used at most once.
#include <map>
#include <string>

#include "compiler/check/passes.h"

namespace ksmc::compiler::check {

void DomainItemsPass::run(Context& ctx) {
  const ast::Loc* first_likelihood = nullptr;
  std::map<std::string, const ast::Loc*> likelihoods;  // likelihood block -> its first use
  int likelihood_module = -1;                          // the module declaring the first one
  std::string likelihood_first;
  std::map<std::string, const ast::Loc*> outputs;  // output block -> its first use
  const ast::Loc* model = nullptr;
  for (const ast::Item& item : ctx.main().items) {
    if (std::holds_alternative<ast::ModelDecl>(item.node) && model == nullptr) model = &item.loc;
    if (const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node)) {
      if (first_likelihood == nullptr) first_likelihood = &item.loc;
      const auto [at, first] = likelihoods.emplace(l->call.name, &l->call.loc);
      if (!first) {
        ctx.diags.error(l->call.loc, "'" + l->call.name + "' is already a likelihood of this domain (at " + ctx.where(*at->second) +
                                         "); several likelihoods are factors over different data, each block once");
      }
      const auto ext = ctx.symbols.externs.find(l->call.name);
      if (first && ext != ctx.symbols.externs.end()) {
        if (likelihood_module < 0) {
          likelihood_module = ext->second.module;
          likelihood_first = l->call.name;
        } else if (ext->second.module != likelihood_module) {
          const auto path = [&](int m) { return ctx.program.modules.at(static_cast<std::size_t>(m)).path; };
          ctx.diags.error(l->call.loc, "the likelihoods of a domain come from one kit: '" + l->call.name + "' is declared in " +
                                           path(ext->second.module) + ", '" + likelihood_first + "' in " + path(likelihood_module));
        }
      }
    }
    if (const auto* o = std::get_if<ast::OutputDecl>(&item.node)) {
      const auto [at, first] = outputs.emplace(o->call.name, &o->call.loc);
      if (!first) ctx.diags.error(o->call.loc, "'" + o->call.name + "' is already an output of this domain (at " + ctx.where(*at->second) + "); the kit reports each output once");
    }
    const auto* p = std::get_if<ast::PriorDecl>(&item.node);
    if (p == nullptr) continue;
    auto it = ctx.symbols.externs.find(p->call.name);
    if (it == ctx.symbols.externs.end() || it->second.decl->kind.name != "prior") continue;  // the calls pass reported it
    const auto& result = it->second.decl->result;
    if (p->quantified && !result) {
      ctx.diags.error(p->call.loc, "'" + p->call.name + "' is a global prior term (no '-> real' result); 'prior for ...:' needs a per-binding term such as 'gaussian'; write 'prior " +
                                       p->call.name + "(...);'");
    } else if (p->quantified && (result->name != "real" || result->list_depth != 0 || result->is_set)) {
      ctx.diags.error(p->call.loc, "a per-binding prior term returns real; '" + p->call.name + "' does not");
    } else if (!p->quantified && result) {
      ctx.diags.error(p->call.loc, "'" + p->call.name + "' is a per-binding prior term ('-> real'); use it as 'prior for VARS where ...: " +
                                       p->call.name + "(...);'");
    }
  }
  if (model != nullptr && first_likelihood == nullptr) {
    ctx.diags.error(*model, "the domain has a model but no likelihood; add 'likelihood KIT_BLOCK(...);'");
  }
}

}  // namespace ksmc::compiler::check
