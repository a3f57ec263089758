// Scores a weight set of a rule base on labelled worlds (.db files with evidence and
// the true query atoms, closed world): for each world, exact inference given the
// evidence alone, then per query predicate the mean log-probability of the true value
// of its atoms (the conditional marginal log-likelihood that MLN papers report as CLL)
// and the accuracy of the decision P > 0.5, and per world the joint conditional
// log-likelihood log P(all true query values | evidence) = log-weight - log Z.
#pragma once

#include <string>
#include <vector>

#include "runtime/mln/program.h"

namespace ksmc::tools::mln_tabletop {

struct PredicateScore {
  std::string name;
  long atoms = 0, correct = 0;
  double log_p = 0.0;  // sum over atoms of log P(true value), each clamped at log 1e-12
  long clamped = 0;    // atoms whose true value had probability below 1e-12
};

struct Evaluation {
  std::vector<PredicateScore> predicates;  // the query predicates, in declaration order
  double joint_cll = 0.0;                  // sum over worlds (feasible ones)
  long worlds = 0, infeasible = 0;         // infeasible: the true world breaks a hard rule
};

// Throws runtime::mln::MlnError (naming the file) on a bad .db.
Evaluation evaluate(const runtime::mln::Program& program, const std::vector<std::string>& db_paths);

}  // namespace ksmc::tools::mln_tabletop
