#include "stdlib/indoor/kit/settings.h"

#include <cmath>
#include <limits>
#include <set>

namespace ksmc::stdlib::indoor::kit {

namespace dom = runtime::domain;

namespace {

[[noreturn]] void fail(const dom::Call& c, const std::string& what) {
  throw dom::ConfigError(c.where + ": " + c.name + ": " + what);
}


Lut read_lut(const dom::Call& c, const std::string& p) {
  const dom::Value& v = c.at(p);
  if (v.kind != dom::Value::Kind::List || v.items.size() != 3) fail(c, "'" + p + "' must be a 3x3 table");
  Lut out{};
  for (std::size_t r = 0; r < 3; ++r) {
    const dom::Value& row = v.items[r];
    if (row.kind != dom::Value::Kind::List || row.items.size() != 3) fail(c, "'" + p + "' row " + std::to_string(r) + " must have 3 entries");
    for (std::size_t k = 0; k < 3; ++k) {
      const dom::Value& x = row.items[k];
      if (x.kind != dom::Value::Kind::Number || !(x.number > 0.0) || !std::isfinite(x.number))
        fail(c, "'" + p + "'[" + std::to_string(r) + "][" + std::to_string(k) + "] must be a positive number");
      out[r][k] = x.number;
    }
  }
  return out;
}

std::vector<std::string> read_names(const dom::Call& c, const std::string& p) {
  const dom::Value& v = c.at(p);
  if (v.kind != dom::Value::Kind::Set && v.kind != dom::Value::Kind::List) fail(c, "'" + p + "' must be a set of names");
  std::vector<std::string> out;
  for (const auto& x : v.items) {
    if (x.kind != dom::Value::Kind::Name && x.kind != dom::Value::Kind::String) fail(c, "'" + p + "' must list names");
    out.push_back(x.text);
  }
  return out;
}

void read_extract(const dom::Extract& e, IndoorSettings& s) {
  const dom::Call& c = e.call;
  const std::string& n = c.name;
  if (n == "geom.room_like" || n == "geom.corridor_like" || n == "geom.hall_like") {
    ClassifierSettings k{c.positive("big_size"), c.positive("big_ratio")};
    if (k.big_ratio < 1.0) fail(c, "big_ratio must be >= 1");
    if (s.semantic.enabled && (k.big_size_m != s.semantic.classifier.big_size_m || k.big_ratio != s.semantic.classifier.big_ratio))
      fail(c, "the three classifier extractors must share big_size and big_ratio");
    s.semantic.classifier = k;
    s.semantic.enabled = true;
  } else if (n == "geom.adjacent") {
    s.semantic.adjacent_dilate_cells = c.non_negative("dilate");
  } else if (n == "geom.multi_door") {
    s.semantic.multi_door_min = c.whole("min_doors", 1);
  } else {
    fail(c, "the indoor kit does not implement this extractor");
  }
}

void read_prior(const dom::Prior& p, IndoorSettings& s) {
  const dom::Call& c = p.call;
  if (c.name == "mln" || c.name.empty()) return;
  if (c.name == "rect_penalty") {
    s.psi1 = c.non_negative("psi1");
    s.tol_rad = c.non_negative("tol");
    if (!p.conditions.empty()) fail(c, "takes no condition");
  } else if (c.name == "overlap_penalty") {
    s.psi2 = c.non_negative("psi2");
    if (!p.conditions.empty()) fail(c, "takes no condition");
  } else if (c.name == "gaussian") {
    const dom::Value& x = c.at("x");
    if (x.kind != dom::Value::Kind::Call || x.text != "wall_length_diff") fail(c, "the indoor kit supports gaussian(wall_length_diff(unit[a], unit[b]), sigma) only");
    if (p.vars.size() != 2 || p.conditions.size() != 1 || !p.conditions[0].probability || p.conditions[0].negated)
      fail(c, "expects `for a, b where P(Pred(a, b)) > t`");
    const dom::Condition& cond = p.conditions[0];
    if (cond.args.size() != 2) fail(c, "the condition's predicate must take two units");
    if (cond.op != ">" && cond.op != ">=") fail(c, "the condition must be `>` or `>=` a threshold");
    s.semantic.sale_prior = true;
    s.semantic.sale_predicate = cond.predicate;
    s.semantic.sale_op = cond.op;
    s.semantic.sale_threshold = cond.threshold;
    s.semantic.sale_sigma_m = c.positive("sigma");
  } else {
    fail(c, "the indoor kit does not implement this prior");
  }
}

void read_source(const dom::Call& c, SourceSettings& s) {
  const std::string& n = c.name;
  if (n == "detect.wbu") {
    s.wbu = true;
    s.wbu_min_size_m = c.positive("min_size");
    s.wbu_max_units = c.whole("max_units", 1);
  } else if (n == "detect.fsu") {
    s.fsu = true;
    s.fsu_after = c.whole("after", 0);
    s.fsu_min_area_cells = c.whole("min_area_cells", 1);
  } else if (n == "detect.rpb") {
    s.rpb = true;
    s.rpb_min_size_m = c.positive("min_size");
  } else if (n == "detect.split_lines") {
    s.split = true;
    s.split_min_votes = c.whole("min_votes", 1);
    s.split_angle_tol_rad = c.non_negative("angle_tol");
  } else if (n == "partner.inverse_distance") {
    // The kernels' partner choice (MERGE, INTERCHANGE) is inverse-distance already.
  } else if (n == "move.wall_shift") {
    s.wall_shift = true;
    s.wall_shift_sigma_cells = c.positive("sigma");
  } else if (n == "detect.doors") {
    s.doors = true;
    s.door_min_width_m = c.positive("min_width");
    s.door_max_width_m = c.positive("max_width");
    if (s.door_max_width_m < s.door_min_width_m) fail(c, "max_width < min_width");
  } else {
    fail(c, "the indoor kit does not implement this proposal source");
  }
}

const std::set<std::string>& kernel_names() {
  static const std::set<std::string> k{"ADD", "REMOVE", "SPLIT", "MERGE", "SHRINK", "DILATE", "ALLOCATE", "DELETE", "INTERCHANGE"};
  return k;
}

}  // namespace

IndoorSettings read_settings(const dom::DomainConfig& config) {
  IndoorSettings s;
  s.lut = {{{0.8, 0.1, 0.1}, {0.1, 0.8, 0.1}, {0.1, 0.1, 0.8}}};
  s.lenient_lut = s.lut;
  for (const auto& e : config.extract) read_extract(e, s);
  for (const auto& p : config.prior) read_prior(p, s);
  if (config.likelihood.size() != 1)
    throw dom::ConfigError(config.source + ": the indoor kit needs exactly one likelihood (grid.occupancy)");
  {
    const dom::Call& c = config.likelihood.front();
    if (c.name != "grid.occupancy") fail(c, "the indoor kit does not implement this likelihood");
    s.lut = read_lut(c, "lut");
    s.lenient_lut = read_lut(c, "lenient_lut");
    s.semantic.lenient_types = read_names(c, "lenient_types");
    for (const auto& t : s.semantic.lenient_types) {
      bool known = false;
      for (const auto& q : s.semantic.type_predicates) known = known || q == t;
      if (!known) fail(c, "lenient type '" + t + "' is not one of Room, Corr, Hall, Other");
    }
  }
  std::set<std::string> seen;
  for (const auto& k : config.kernels) {
    if (!kernel_names().count(k.name) || !kernel_names().count(k.reverse))
      throw dom::ConfigError(k.where + ": kernel " + k.name + ": the indoor kit implements ADD/REMOVE, SPLIT/MERGE, SHRINK/DILATE, ALLOCATE/DELETE and INTERCHANGE only");
    if (!seen.insert(k.name).second) throw dom::ConfigError(k.where + ": kernel " + k.name + " declared twice");
    if (!k.params.empty()) throw dom::ConfigError(k.where + ": kernel " + k.name + ": the indoor kernels take no parameters");
    for (const auto& src : k.sources) read_source(src, s.sources);
    s.kernels.emplace_back(k.name, k.reverse);
  }
  if (s.kernels.empty()) throw dom::ConfigError(config.source + ": the indoor kit needs at least one kernel");
  if (!s.sources.wbu && !s.sources.fsu && !s.sources.rpb)
    throw dom::ConfigError(config.source + ": no unit source (detect.wbu, detect.fsu or detect.rpb) for ADD");
  for (const auto& r : config.schedule) {
    ScheduleRowSettings row;
    if (r.begin < 0 || r.end <= r.begin) throw dom::ConfigError(config.source + ": schedule row [" + std::to_string(r.begin) + ", ...) is empty or negative");
    row.begin = static_cast<std::uint64_t>(r.begin);
    row.end = r.end == dom::ScheduleRow::kForever ? std::numeric_limits<std::uint64_t>::max() : static_cast<std::uint64_t>(r.end);
    row.probabilities = r.probabilities;
    s.schedule.push_back(std::move(row));
  }
  if (s.schedule.empty()) throw dom::ConfigError(config.source + ": the indoor kit needs a schedule");
  return s;
}

}  // namespace ksmc::stdlib::indoor::kit
