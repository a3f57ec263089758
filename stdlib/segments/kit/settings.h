// The segments kit's reading of a DomainConfig (runtime/domain/config.h): the model's
// segment collection, the extractors (seg.*), the priors (seg.complexity, mln, semantic
// gaussian terms), the likelihood (points.gaussian), the kernels by their proposal sources
// and the schedule, all in base units. Anything the kit cannot honour is a ConfigError
// naming the call's `file:line`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/domain/config.h"
#include "stdlib/segments/detect.h"
#include "stdlib/segments/proposals.h"
#include "stdlib/segments/scene.h"

namespace ksmc::stdlib::segments::kit {

enum class Relation { Touching, Perpendicular, Parallel, Close, Short };

struct ExtractSpec {
  std::string predicate;
  Relation relation = Relation::Touching;
  double param = 0.0;  // gap / tol / dist / max_length in metres or radians
  std::size_t arity = 2;
  std::string where;
};

enum class Measure { EndpointGap, LineOffset, CornerAngleError, ParallelAngleError };

struct ConditionSpec {
  bool probability = false;   // P(q(...)) op t, else an evidence atom
  bool negated = false;
  std::string predicate;
  std::vector<std::size_t> args;  // indices into the term's vars
  std::string op;
  double threshold = 0.0;
};

// `prior for a, b where ...: gaussian(measure(line[a], line[b]), sigma)`.
struct SemanticTermSpec {
  std::vector<std::string> vars;
  std::vector<ConditionSpec> conditions;
  Measure measure = Measure::EndpointGap;
  std::size_t arg_a = 0, arg_b = 1;  // indices into vars
  double sigma = 0.03;
  std::string where;
};

enum class KernelKind { Birth, Death, Split, Merge, Jitter };

struct KernelSpec {
  std::string name, reverse;
  KernelKind kind = KernelKind::Jitter;
};

struct JitterParams {
  double sigma = 0.02;
  double shift_prob = 0.2;
  double slide = 0.05;
  double slide_prob = 0.4;
};

struct ScheduleRowSpec {
  std::uint64_t begin = 0, end = 0;
  std::vector<std::pair<std::string, double>> probabilities;
};

struct SegmentsSettings {
  std::string collection = "line";  // the model's segment collection = the MLN type's name
  std::vector<ExtractSpec> extracts;
  bool complexity = false;
  double per_segment = 0.0, per_metre = 0.0;
  bool mln_prior = false;
  std::vector<SemanticTermSpec> terms;
  LikelihoodParams likelihood;
  RansacParams ransac;
  BirthParams birth;
  DeathParams death;
  SplitParams split;
  MergeParams merge;
  JitterParams jitter;
  std::vector<KernelSpec> kernels;
  std::vector<ScheduleRowSpec> schedule;
};

SegmentsSettings read_settings(const runtime::domain::DomainConfig& config);

}  // namespace ksmc::stdlib::segments::kit
