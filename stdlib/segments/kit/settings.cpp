#include "stdlib/segments/kit/settings.h"

#include <cmath>
#include <limits>
#include <set>

namespace ksmc::stdlib::segments::kit {

namespace dom = runtime::domain;

namespace {

[[noreturn]] void fail(const dom::Call& c, const std::string& what) {
  throw dom::ConfigError(c.where + ": " + c.name + ": " + what);
}


// `line[v]`: the name of the index variable (and checks the collection).
std::string index_var(const dom::Call& c, const dom::Value& v, const std::string& collection) {
  if (v.kind != dom::Value::Kind::Index || v.text != collection || v.items.size() != 1 ||
      v.items[0].kind != dom::Value::Kind::Name)
    fail(c, "expects the segments as " + collection + "[var]");
  return v.items[0].text;
}

void read_extract(const dom::Extract& e, SegmentsSettings& s) {
  const dom::Call& c = e.call;
  ExtractSpec x;
  x.predicate = e.predicate;
  x.where = c.where;
  std::vector<std::string> args;
  if (c.name == "seg.short") {
    x.relation = Relation::Short;
    x.arity = 1;
    args.push_back(index_var(c, c.at("s"), s.collection));
    x.param = c.positive("max_length");
  } else {
    if (c.name == "seg.touching") {
      x.relation = Relation::Touching;
      x.param = c.non_negative("gap");
    } else if (c.name == "seg.perpendicular") {
      x.relation = Relation::Perpendicular;
      x.param = c.non_negative("tol");
    } else if (c.name == "seg.parallel") {
      x.relation = Relation::Parallel;
      x.param = c.non_negative("tol");
    } else if (c.name == "seg.close") {
      x.relation = Relation::Close;
      x.param = c.non_negative("dist");
    } else {
      fail(c, "the segments kit does not implement this extractor");
    }
    args.push_back(index_var(c, c.at("a"), s.collection));
    args.push_back(index_var(c, c.at("b"), s.collection));
  }
  if (args != e.vars) fail(c, "the arguments must index " + s.collection + " by the atom's variables in order");
  s.extracts.push_back(std::move(x));
}

Measure read_measure(const dom::Call& c, const dom::Value& x, bool angle) {
  if (x.kind != dom::Value::Kind::Call) fail(c, "expects a measure function of two segments as 'x'");
  if (!angle && x.text == "endpoint_gap") return Measure::EndpointGap;
  if (!angle && x.text == "line_offset") return Measure::LineOffset;
  if (angle && x.text == "corner_angle_error") return Measure::CornerAngleError;
  if (angle && x.text == "parallel_angle_error") return Measure::ParallelAngleError;
  fail(c, "the segments kit does not implement the function '" + x.text + "' here");
}

std::size_t var_index(const dom::Call& c, const std::vector<std::string>& vars, const std::string& v) {
  for (std::size_t i = 0; i < vars.size(); ++i)
    if (vars[i] == v) return i;
  fail(c, "'" + v + "' is not one of the term's variables");
}

void read_prior(const dom::Prior& p, SegmentsSettings& s) {
  const dom::Call& c = p.call;
  if (c.name == "mln") {
    if (!p.vars.empty()) fail(c, "takes no variables");
    s.mln_prior = true;
  } else if (c.name == "seg.complexity") {
    if (!p.vars.empty()) fail(c, "takes no variables");
    s.complexity = true;
    s.per_segment = c.non_negative("per_segment");
    s.per_metre = c.non_negative("per_metre");
  } else if (c.name == "gaussian" || c.name == "gaussian_angle") {
    SemanticTermSpec t;
    t.where = c.where;
    t.vars = p.vars;
    if (t.vars.empty() || t.vars.size() > 3) fail(c, "expects `for a, b where ...` with one to three variables");
    const dom::Value& x = c.at("x");
    t.measure = read_measure(c, x, c.name == "gaussian_angle");
    if (x.items.size() != 2) fail(c, "the measure takes two segments");
    t.arg_a = var_index(c, t.vars, index_var(c, x.items[0], s.collection));
    t.arg_b = var_index(c, t.vars, index_var(c, x.items[1], s.collection));
    t.sigma = c.positive("sigma");
    for (const dom::Condition& k : p.conditions) {
      ConditionSpec cs;
      cs.probability = k.probability;
      cs.negated = k.negated;
      cs.predicate = k.predicate;
      cs.op = k.op;
      cs.threshold = k.threshold;
      for (const auto& a : k.args) cs.args.push_back(var_index(c, t.vars, a));
      if (cs.probability && cs.op != ">" && cs.op != ">=" && cs.op != "<" && cs.op != "<=")
        fail(c, "unknown comparison '" + cs.op + "'");
      t.conditions.push_back(std::move(cs));
    }
    s.terms.push_back(std::move(t));
  } else {
    fail(c, "the segments kit does not implement this prior");
  }
}

// Kind of a kernel direction from its sources; `forward`: the first-declared direction.
KernelKind kernel_kind(const dom::Kernel& k, bool forward) {
  bool birth = false, death = false, split = false, merge = false, jitter = false;
  for (const auto& c : k.sources) {
    if (c.name == "detect.ransac") birth = true;
    else if (c.name == "support.poor") death = true;
    else if (c.name == "detect.gaps") split = true;
    else if (c.name == "partner.inverse_gap") merge = true;
    else if (c.name == "move.endpoint_jitter") jitter = true;
    else fail(c, "the segments kit does not implement this proposal source");
  }
  const int families = (birth || death ? 1 : 0) + (split || merge ? 1 : 0) + (jitter ? 1 : 0);
  if (families != 1)
    throw dom::ConfigError(k.where + ": kernel " + k.name +
                           ": give the sources of one move: detect.ransac + support.poor (birth/death), "
                           "detect.gaps + partner.inverse_gap (split/merge) or move.endpoint_jitter");
  if (jitter) {
    if (k.name != k.reverse) throw dom::ConfigError(k.where + ": kernel " + k.name + ": move.endpoint_jitter is its own reverse");
    return KernelKind::Jitter;
  }
  if (k.name == k.reverse)
    throw dom::ConfigError(k.where + ": kernel " + k.name + ": birth/death and split/merge need a pair `kernel pair A / B`");
  if (birth || death) {
    if (!birth) throw dom::ConfigError(k.where + ": kernel " + k.name + ": birth/death needs detect.ransac");
    return forward ? KernelKind::Birth : KernelKind::Death;
  }
  return forward ? KernelKind::Split : KernelKind::Merge;
}

void read_source(const dom::Call& c, SegmentsSettings& s) {
  if (c.name == "detect.ransac") {
    s.ransac.min_inliers = c.whole("min_inliers", 2, 1000000);
    s.ransac.inlier_dist = c.positive("inlier_dist");
    s.ransac.candidates = c.whole("candidates", 1, 100000);
    s.ransac.max_gap = c.positive("max_gap");
    s.birth.jitter = c.positive("jitter");
    s.birth.power = c.non_negative("power");
    s.birth.explained = s.ransac.inlier_dist;
  } else if (c.name == "support.poor") {
    s.death.explain = c.positive("explain");
  } else if (c.name == "detect.gaps") {
    s.split.bin = c.positive("bin");
    s.split.gap_weight = c.positive("gap_weight");
    s.split.jitter = c.positive("jitter");
    s.split.near = c.positive("near");
  } else if (c.name == "partner.inverse_gap") {
    s.merge.eps = c.positive("eps");
    s.merge.angle_scale = c.positive("angle_scale");
  } else if (c.name == "move.endpoint_jitter") {
    s.jitter.sigma = c.positive("sigma");
    s.jitter.shift_prob = c.number("shift_prob");
    s.jitter.slide = c.positive("slide");
    s.jitter.slide_prob = c.number("slide_prob");
    if (!(s.jitter.shift_prob >= 0.0 && s.jitter.slide_prob >= 0.0 && s.jitter.shift_prob + s.jitter.slide_prob <= 1.0))
      fail(c, "shift_prob and slide_prob must be >= 0 with a sum of at most 1");
  }
}

}  // namespace

SegmentsSettings read_settings(const dom::DomainConfig& config) {
  SegmentsSettings s;
  if (config.model.size() != 1 || !config.model[0].collection || !config.model[0].index_type.empty() ||
      config.model[0].value_type != "segment" || !config.model[0].sampled)
    throw dom::ConfigError(config.source + ": the segments kit needs a model of exactly one variable-size collection "
                           "`name[] : segment sampled`");
  s.collection = config.model[0].name;
  for (const auto& e : config.extract) read_extract(e, s);
  for (const auto& p : config.prior) read_prior(p, s);
  if (config.likelihood.size() != 1)
    throw dom::ConfigError(config.source + ": the segments kit needs exactly one likelihood (points.gaussian)");
  const dom::Call& lc = config.likelihood.front();
  if (lc.name != "points.gaussian") fail(lc, "the segments kit does not implement this likelihood");
  s.likelihood.sigma = lc.positive("sigma");
  s.likelihood.background = lc.number("background");
  if (!(s.likelihood.background > 0.0 && s.likelihood.background < 1.0)) fail(lc, "background must be in (0, 1)");

  std::set<std::string> seen;
  for (const auto& k : config.kernels) {
    if (!seen.insert(k.name).second) throw dom::ConfigError(k.where + ": kernel " + k.name + " declared twice");
    if (!k.params.empty()) throw dom::ConfigError(k.where + ": kernel " + k.name + ": the segment kernels take no parameters");
    const bool forward = seen.count(k.reverse) == 0 || k.reverse == k.name;
    for (const auto& src : k.sources) read_source(src, s);
    s.kernels.push_back({k.name, k.reverse, kernel_kind(k, forward)});
  }
  if (s.kernels.empty()) throw dom::ConfigError(config.source + ": the segments kit needs at least one kernel");
  for (const auto& r : config.schedule) {
    if (r.begin < 0 || r.end <= r.begin)
      throw dom::ConfigError(config.source + ": schedule row [" + std::to_string(r.begin) + ", ...) is empty or negative");
    ScheduleRowSpec row;
    row.begin = static_cast<std::uint64_t>(r.begin);
    row.end = r.end == dom::ScheduleRow::kForever ? std::numeric_limits<std::uint64_t>::max()
                                                  : static_cast<std::uint64_t>(r.end);
    row.probabilities = r.probabilities;
    s.schedule.push_back(std::move(row));
  }
  if (s.schedule.empty()) throw dom::ConfigError(config.source + ": the segments kit needs a schedule");
  return s;
}

}  // namespace ksmc::stdlib::segments::kit
