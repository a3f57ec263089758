// A first-order clause program: the runtime contract the compiler lowers rule bases
// to (no compiler dependency). Types are names; their constants are supplied at run
// time (Domain). Predicates are evidence (closed world) or query (free unless given).
// Clauses are disjunctions of literals over typed variables; existential variables
// are expanded into a disjunction over their domain when grounding. Each clause keeps
// its source text and location for messages.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ksmc::runtime::mln {

struct SourceLoc {
  std::string file;
  std::int32_t line = 0;
  // "file:line"; the file alone when the line is 0 (generated code records no line, so an
  // edit above a rule leaves its code unchanged).
  std::string str() const {
    if (file.empty()) return "<program>";
    return line > 0 ? file + ":" + std::to_string(line) : file;
  }
};

struct Predicate {
  std::string name;
  std::vector<std::int32_t> arg_types;   // type ids
  bool query = false;                    // false: evidence predicate (closed world)
  bool query_evidence_allowed = false;   // query atoms may be fixed by a .db file
  std::int32_t exclusive_arg = -1;       // Alchemy `p(x, t!)`: exactly one t per other args
  bool auxiliary = false;                // introduced by a rewrite (per-formula weights): not reported
};

// "exactly one of P1(args), ..., Pk(args)" for every binding; predicates share arg types.
struct ExactlyOneGroup {
  std::vector<std::int32_t> predicates;
  std::string text;
  SourceLoc loc;
};

struct Variable {
  std::string name;
  std::int32_t type = 0;
  bool existential = false;
};

struct Term {
  bool is_variable = true;
  std::int32_t variable = 0;  // index into Clause::variables
  std::string constant;       // when !is_variable
  static Term var(std::int32_t v) { return Term{true, v, {}}; }
  static Term cst(std::string c) { return Term{false, 0, std::move(c)}; }
};

struct Literal {
  std::int32_t predicate = 0;
  bool negated = false;
  std::vector<Term> args;
};

struct Clause {
  std::string name;                 // e.g. "r10"
  std::vector<Variable> variables;
  std::vector<Literal> literals;    // disjunction
  double weight = 0.0;
  bool hard = false;
  std::string text;                 // the formula it came from
  SourceLoc loc;
  std::string describe() const;     // "r10 `text` (file:line)"
};

class Program {
 public:
  std::int32_t add_type(const std::string& name);
  std::int32_t add_predicate(Predicate p);
  void add_group(ExactlyOneGroup g) { groups.push_back(std::move(g)); }
  void add_clause(Clause c) { clauses.push_back(std::move(c)); }

  std::optional<std::int32_t> find_type(const std::string& name) const;
  std::optional<std::int32_t> find_predicate(const std::string& name) const;
  // Throws MlnError if ids are out of range, arities or types mismatch, etc.
  void validate() const;

  std::vector<std::string> types;
  std::vector<Predicate> predicates;
  std::vector<ExactlyOneGroup> groups;
  std::vector<Clause> clauses;

 private:
  std::map<std::string, std::int32_t> type_index_;
  std::map<std::string, std::int32_t> predicate_index_;
};

// Constants per type, supplied at run time.
class Domain {
 public:
  explicit Domain(std::size_t num_types = 0) : constants_(num_types), index_(num_types) {}
  void resize(std::size_t num_types) { constants_.resize(num_types); index_.resize(num_types); }
  // Adds a constant (idempotent); returns its index within the type.
  std::int32_t add(std::int32_t type, const std::string& name);
  std::optional<std::int32_t> find(std::int32_t type, const std::string& name) const;
  const std::vector<std::string>& constants(std::int32_t type) const { return constants_[type]; }
  std::int32_t size(std::int32_t type) const { return static_cast<std::int32_t>(constants_[type].size()); }
  std::size_t num_types() const { return constants_.size(); }

 private:
  std::vector<std::vector<std::string>> constants_;
  std::vector<std::map<std::string, std::int32_t>> index_;
};

}  // namespace ksmc::runtime::mln
