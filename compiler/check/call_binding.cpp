#include "compiler/check/call_binding.h"

namespace ksmc::compiler::check {

std::vector<BoundArg> bind_call(const ast::Call& call, const ast::ExternDecl& decl) {
  std::vector<BoundArg> out(decl.params.size());
  for (std::size_t i = 0; i < decl.params.size(); ++i) out[i].param = &decl.params[i];
  std::size_t positional = 0;
  for (const ast::Arg& a : call.args) {
    if (!a.name) {
      if (positional < out.size()) out[positional++].value = &a.value;
      continue;
    }
    for (std::size_t i = 0; i < decl.params.size(); ++i)
      if (decl.params[i].name.name == a.name->name && out[i].value == nullptr) out[i].value = &a.value;
  }
  for (BoundArg& b : out) {
    if (b.value == nullptr && b.param->default_value) {
      b.value = &*b.param->default_value;
      b.defaulted = true;
    }
  }
  return out;
}

double unit_scale(const SymbolTable& symbols, const std::string& unit) {
  if (unit.empty()) return 1.0;
  auto it = symbols.units.find(unit);
  return it == symbols.units.end() ? 1.0 : it->second.scale;
}

double base_value(const SymbolTable& symbols, const ast::Number& n) { return n.value * unit_scale(symbols, n.unit); }

std::string constant_type(const ast::Module& main, const SymbolTable& symbols) {
  for (const ast::Item& item : main.items) {
    const auto* m = std::get_if<ast::ModelDecl>(&item.node);
    if (m == nullptr) continue;
    for (const ast::ModelVar& v : m->vars) {
      auto it = symbols.model_vars.find(v.name.name);
      if (it != symbols.model_vars.end() && symbols.is_domain_type(it->second.element_type)) return it->second.element_type;
    }
  }
  return {};
}

const ast::ModelContractDecl* model_contract(const ast::Program& program, const SymbolTable& symbols) {
  int kit_module = -1;
  for (const ast::Item& item : program.modules.front().items) {
    if (const auto* l = std::get_if<ast::LikelihoodDecl>(&item.node)) {
      auto it = symbols.externs.find(l->call.name);
      if (it != symbols.externs.end()) kit_module = it->second.module;
    }
  }
  for (const auto& [decl, module] : symbols.model_contracts)
    if (module == kit_module) return decl;
  return symbols.model_contracts.size() == 1 ? symbols.model_contracts.front().first : nullptr;
}

}  // namespace ksmc::compiler::check
