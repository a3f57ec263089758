// The lowered Markov logic part of a domain: the runtime clause program plus, per source
// rule, what the generated code and `--dump-ir` need to name and annotate it.
#pragma once

#include <string>
#include <vector>

#include "runtime/mln/program.h"

namespace ksmc::compiler::lower {

struct RuleIr {
  enum class WeightKind { Hard, Prob, Raw };
  int number = 0;            // 1-based position among the main file's rules
  std::string name;          // `@name`, or content-derived: "supportive_supported_3fa1" (check/rule_names.h)
  std::string text;          // the rule as written
  std::string file;          // as given on the command line
  int line = 0;
  WeightKind kind = WeightKind::Hard;
  std::string written;       // the weight as spelled: "0.7" for `prob 0.7`, "1.5" for `w 1.5`
  double weight = 0.0;       // log-odds of prob, the raw weight, or +inf for hard
  std::vector<int> clauses;  // indices into MlnIr::program.clauses (weight split evenly)
  int group = -1;            // `exactly one of`: index into program.groups
};

struct MlnIr {
  std::string domain;
  runtime::mln::Program program;
  // Per type id: the constants of an enumerated type (`type kind = {A, B};`); empty for
  // types whose constants come at run time.
  std::vector<std::vector<std::string>> enumerated;
  std::vector<RuleIr> rules;
};

}  // namespace ksmc::compiler::lower
