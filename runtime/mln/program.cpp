#include "runtime/mln/program.h"

#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {

std::string Clause::describe() const {
  std::string out = name.empty() ? std::string("rule") : name;
  if (!text.empty()) out += " `" + text + "`";
  out += " (" + loc.str() + ")";
  return out;
}

std::int32_t Program::add_type(const std::string& name) {
  if (type_index_.count(name)) throw MlnError("program: duplicate type '" + name + "'");
  const auto id = static_cast<std::int32_t>(types.size());
  types.push_back(name);
  type_index_[name] = id;
  return id;
}

std::int32_t Program::add_predicate(Predicate p) {
  if (predicate_index_.count(p.name)) throw MlnError("program: duplicate predicate '" + p.name + "'");
  const auto id = static_cast<std::int32_t>(predicates.size());
  predicate_index_[p.name] = id;
  predicates.push_back(std::move(p));
  return id;
}

std::optional<std::int32_t> Program::find_type(const std::string& name) const {
  const auto it = type_index_.find(name);
  if (it == type_index_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::int32_t> Program::find_predicate(const std::string& name) const {
  const auto it = predicate_index_.find(name);
  if (it == predicate_index_.end()) return std::nullopt;
  return it->second;
}

void Program::validate() const {
  const auto nt = static_cast<std::int32_t>(types.size());
  const auto np = static_cast<std::int32_t>(predicates.size());
  for (const auto& p : predicates) {
    for (auto t : p.arg_types)
      if (t < 0 || t >= nt) throw MlnError("program: predicate '" + p.name + "' has an unknown argument type");
    if (p.exclusive_arg >= static_cast<std::int32_t>(p.arg_types.size()))
      throw MlnError("program: predicate '" + p.name + "' marks a non-existent argument as exclusive (!)");
  }
  for (const auto& g : groups) {
    if (g.predicates.empty()) throw MlnError(g.loc.str() + ": empty exactly-one group");
    for (auto q : g.predicates) {
      if (q < 0 || q >= np) throw MlnError(g.loc.str() + ": exactly-one group names an unknown predicate");
      if (predicates[q].arg_types != predicates[g.predicates[0]].arg_types)
        throw MlnError(g.loc.str() + ": predicates of an exactly-one group must have the same argument types ('" +
                       predicates[q].name + "' differs from '" + predicates[g.predicates[0]].name + "')");
    }
  }
  for (const auto& c : clauses) {
    if (!c.hard && !(c.weight == c.weight && c.weight - c.weight == 0.0))
      throw MlnError(c.describe() + ": soft weight must be finite");
    for (const auto& v : c.variables)
      if (v.type < 0 || v.type >= nt) throw MlnError(c.describe() + ": variable '" + v.name + "' has an unknown type");
    for (const auto& l : c.literals) {
      if (l.predicate < 0 || l.predicate >= np) throw MlnError(c.describe() + ": unknown predicate");
      const auto& p = predicates[l.predicate];
      if (l.args.size() != p.arg_types.size())
        throw MlnError(c.describe() + ": '" + p.name + "' takes " + std::to_string(p.arg_types.size()) +
                       (p.arg_types.size() == 1 ? " argument" : " arguments") + ", got " +
                       std::to_string(l.args.size()));
      for (std::size_t i = 0; i < l.args.size(); ++i) {
        const auto& t = l.args[i];
        if (!t.is_variable) continue;
        if (t.variable < 0 || t.variable >= static_cast<std::int32_t>(c.variables.size()))
          throw MlnError(c.describe() + ": literal of '" + p.name + "' uses an unknown variable");
        if (c.variables[t.variable].type != p.arg_types[i])
          throw MlnError(c.describe() + ": variable '" + c.variables[t.variable].name + "' has type '" +
                         types[c.variables[t.variable].type] + "' but argument " + std::to_string(i + 1) +
                         " of '" + p.name + "' has type '" + types[p.arg_types[i]] + "'");
      }
    }
  }
}

std::int32_t Domain::add(std::int32_t type, const std::string& name) {
  if (index_.size() < constants_.size()) index_.resize(constants_.size());
  auto& idx = index_[type];
  const auto it = idx.find(name);
  if (it != idx.end()) return it->second;
  const auto id = static_cast<std::int32_t>(constants_[type].size());
  constants_[type].push_back(name);
  idx[name] = id;
  return id;
}

std::optional<std::int32_t> Domain::find(std::int32_t type, const std::string& name) const {
  if (type < 0 || static_cast<std::size_t>(type) >= index_.size()) return std::nullopt;
  const auto it = index_[type].find(name);
  if (it == index_[type].end()) return std::nullopt;
  return it->second;
}

}  // namespace ksmc::runtime::mln
