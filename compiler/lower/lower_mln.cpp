#include "compiler/lower/lower_mln.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "compiler/check/rule_names.h"
#include "compiler/lower/cnf.h"
#include "compiler/lower/dump_ir.h"

namespace ksmc::compiler::lower {
namespace {

namespace mln = ksmc::runtime::mln;

class Lowerer {
 public:
  Lowerer(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources,
          diag::DiagEngine& diags, MlnIr& out)
      : program_(program), symbols_(symbols), sources_(sources), diags_(diags), out_(out) {}

  bool run() {
    out_.domain = symbols_.domain;
    for (const auto& m : program_.modules)
      for (const auto& item : m.items) {
        if (const auto* t = std::get_if<ast::TypeDecl>(&item.node)) add_type(*t);
      }
    for (const auto& m : program_.modules)
      for (const auto& item : m.items) {
        if (const auto* p = std::get_if<ast::PredDecl>(&item.node)) add_predicates(*p);
      }
    const auto& main = program_.modules.front();
    int number = 0;
    bool ok = true;
    for (const auto& item : main.items) {
      if (const auto* r = std::get_if<ast::Rule>(&item.node)) ok = add_rule(++number, *r, item.loc) && ok;
    }
    return ok;
  }

 private:
  void add_type(const ast::TypeDecl& t) {
    const auto id = out_.program.add_type(t.name.name);
    if (out_.enumerated.size() <= static_cast<std::size_t>(id)) out_.enumerated.resize(static_cast<std::size_t>(id) + 1);
    if (t.enumerated)
      for (const auto& c : t.constants) out_.enumerated[static_cast<std::size_t>(id)].push_back(c.name);
  }

  void add_predicates(const ast::PredDecl& d) {
    for (const auto& sig : d.preds) {
      mln::Predicate p;
      p.name = sig.name.name;
      p.query = d.query;
      for (std::size_t i = 0; i < sig.args.size(); ++i) {
        p.arg_types.push_back(*out_.program.find_type(sig.args[i].type.name));
        if (sig.args[i].exclusive) p.exclusive_arg = static_cast<std::int32_t>(i);
      }
      out_.program.add_predicate(std::move(p));
    }
  }

  bool is_constant(const std::string& name) const { return symbols_.constants.count(name) > 0; }

  mln::SourceLoc source_loc(const ast::Loc& loc) const {
    return mln::SourceLoc{sources_.path(loc.file), loc.line};
  }

  // The rule's formula as written, on one line, without its weight prefix (`hard`,
  // `prob p:`, `w x:`) and final period: a weight edit then leaves the text unchanged.
  static std::string formula_text(const ast::Rule& r) {
    std::string t = one_line(r.source_text);
    if (r.prob || r.weight) {
      const auto colon = t.find(':');
      if (colon != std::string::npos) t = t.substr(colon + 1);
    } else if (r.hard && t.rfind("hard", 0) == 0) {
      t = t.substr(4);
    }
    while (!t.empty() && (t.front() == ' ')) t.erase(t.begin());
    while (!t.empty() && (t.back() == ' ' || t.back() == '.')) t.pop_back();
    return t;
  }

  bool add_rule(int number, const ast::Rule& r, const ast::Loc& loc) {
    RuleIr ir;
    ir.number = number;
    const auto named = symbols_.rule_names.find(&r);
    ir.name = named != symbols_.rule_names.end() ? named->second : check::rule_name(r);
    ir.text = formula_text(r);
    ir.file = sources_.path(loc.file);
    ir.line = loc.line;
    if (r.hard) {
      ir.kind = RuleIr::WeightKind::Hard;
      ir.weight = std::numeric_limits<double>::infinity();
    } else if (r.prob) {
      ir.kind = RuleIr::WeightKind::Prob;
      ir.written = r.prob->text;
      ir.weight = std::log(r.prob->value / (1.0 - r.prob->value));
    } else if (r.weight) {
      ir.kind = RuleIr::WeightKind::Raw;
      ir.written = r.weight->text;
      ir.weight = r.weight->value;
    }

    if (r.exactly_one) {
      mln::ExactlyOneGroup g;
      for (const auto& a : r.alternatives) g.predicates.push_back(*out_.program.find_predicate(a.pred.name));
      g.text = ir.text;
      g.loc = source_loc(loc);
      ir.group = static_cast<int>(out_.program.groups.size());
      out_.program.add_group(std::move(g));
      out_.rules.push_back(std::move(ir));
      return true;
    }

    CnfResult cnf = to_cnf(r.formula, [this](const std::string& n) { return is_constant(n); });
    if (!cnf.error.empty()) {
      diags_.error(cnf.error_loc, cnf.error);
      return false;
    }
    const double per_clause = r.hard ? ir.weight : ir.weight / static_cast<double>(cnf.clauses.size());
    for (std::size_t k = 0; k < cnf.clauses.size(); ++k) {
      const auto& cc = cnf.clauses[k];
      mln::Clause c;
      c.name = cnf.clauses.size() == 1 ? ir.name : ir.name + "_c" + std::to_string(k + 1);
      c.hard = r.hard;
      c.weight = per_clause;
      c.text = ir.text;
      c.loc = source_loc(loc);
      std::map<std::string, std::int32_t> var_index;
      for (const auto& lit : cc.literals) {
        mln::Literal l;
        l.predicate = *out_.program.find_predicate(lit.atom->pred.name);
        l.negated = lit.negated;
        const auto& types = out_.program.predicates[static_cast<std::size_t>(l.predicate)].arg_types;
        for (std::size_t i = 0; i < lit.args.size(); ++i) {
          const std::string& a = lit.args[i];
          if (is_constant(a) && lit.atom->args[i].name == a) {
            l.args.push_back(mln::Term::cst(a));
            continue;
          }
          auto it = var_index.find(a);
          if (it == var_index.end()) {
            mln::Variable v;
            v.name = a;
            v.type = types[i];
            v.existential = std::find(cc.existential.begin(), cc.existential.end(), a) != cc.existential.end();
            it = var_index.emplace(a, static_cast<std::int32_t>(c.variables.size())).first;
            c.variables.push_back(std::move(v));
          }
          l.args.push_back(mln::Term::var(it->second));
        }
        c.literals.push_back(std::move(l));
      }
      ir.clauses.push_back(static_cast<int>(out_.program.clauses.size()));
      out_.program.add_clause(std::move(c));
    }
    out_.rules.push_back(std::move(ir));
    return true;
  }

  const ast::Program& program_;
  const check::SymbolTable& symbols_;
  const diag::SourceManager& sources_;
  diag::DiagEngine& diags_;
  MlnIr& out_;
};

}  // namespace

bool lower_mln(const ast::Program& program, const check::SymbolTable& symbols, const diag::SourceManager& sources,
               diag::DiagEngine& diags, MlnIr& out) {
  return Lowerer(program, symbols, sources, diags, out).run();
}

}  // namespace ksmc::compiler::lower
