#include "compiler/check/scopes.h"

namespace ksmc::compiler::check {

void for_each_atom(const ast::Formula& f, const std::function<void(const ast::Atom&)>& fn) {
  if (f.kind == ast::Formula::Kind::Atom) {
    fn(f.atom);
    return;
  }
  for (const ast::Formula& c : f.children) for_each_atom(c, fn);
}

namespace {

void collect_binders(const ast::Formula& f, std::vector<const ast::Ident*>& out) {
  if (f.kind == ast::Formula::Kind::Exists) {
    for (const ast::Ident& v : f.vars) out.push_back(&v);
  }
  for (const ast::Formula& c : f.children) collect_binders(c, out);
}

}  // namespace

std::vector<Scope> collect_scopes(const ast::Module& m) {
  std::vector<Scope> scopes;
  for (const ast::Item& item : m.items) {
    Scope s;
    s.item = &item;
    if (const auto* r = std::get_if<ast::Rule>(&item.node)) {
      s.kind = Scope::Kind::Rule;
      if (r->exactly_one) {
        for (const ast::Atom& a : r->alternatives) s.atoms.push_back(&a);
      } else {
        for_each_atom(r->formula, [&](const ast::Atom& a) { s.atoms.push_back(&a); });
        collect_binders(r->formula, s.binders);
      }
    } else if (const auto* e = std::get_if<ast::ExtractDecl>(&item.node)) {
      s.kind = Scope::Kind::Extract;
      s.atoms.push_back(&e->target);
      s.calls.push_back(&e->call);
    } else if (const auto* p = std::get_if<ast::PriorDecl>(&item.node)) {
      s.kind = Scope::Kind::Prior;
      for (const ast::Condition& c : p->conditions) s.atoms.push_back(&c.atom);
      for (const ast::Ident& v : p->vars) s.binders.push_back(&v);
      s.calls.push_back(&p->call);
    } else if (const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node)) {
      s.kind = Scope::Kind::Prior;
      s.calls.push_back(&l->call);
    } else if (const auto* o = std::get_if<ast::OutputDecl>(&item.node)) {
      s.kind = Scope::Kind::Output;
      s.calls.push_back(&o->call);
    } else if (const auto* k = std::get_if<ast::KernelDecl>(&item.node)) {
      s.kind = Scope::Kind::Kernel;
      for (const ast::KernelParam& kp : k->params) s.declared[kp.name.name] = kp.type.name;
      for (const ast::Call& c : k->sources) s.calls.push_back(&c);
    } else {
      continue;
    }
    scopes.push_back(std::move(s));
  }
  return scopes;
}

std::map<std::string, VarType> infer_variable_types(const Scope& scope, const SymbolTable& symbols,
                                                    const ConflictFn& conflict) {
  std::map<std::string, VarType> types;
  for (const auto& [name, type] : scope.declared) types[name] = VarType{type, scope.item->loc};
  for (const ast::Atom* a : scope.atoms) {
    const PredicateSym* p = symbols.predicate(a->pred.name);
    for (std::size_t i = 0; i < a->args.size(); ++i) {
      const ast::Ident& arg = a->args[i];
      if (symbols.constants.count(arg.name) != 0) continue;
      std::string type;
      if (p != nullptr && i < p->decl->args.size()) type = p->decl->args[i].type.name;
      auto it = types.find(arg.name);
      if (it == types.end()) {
        types[arg.name] = VarType{type, arg.loc};
      } else if (it->second.type.empty()) {
        it->second = VarType{type, arg.loc};
      } else if (!type.empty() && type != it->second.type && conflict) {
        conflict(arg.name, it->second, type, arg.loc);
      }
    }
  }
  return types;
}

}  // namespace ksmc::compiler::check
