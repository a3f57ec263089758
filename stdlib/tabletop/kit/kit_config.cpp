#include "stdlib/tabletop/kit/kit_config.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include <fmt/format.h>

namespace ksmc::stdlib::tabletop::kit {

namespace rd = ksmc::runtime::domain;

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw rd::ConfigError(where + ": " + what);
}

std::string place(const std::string& where, const rd::DomainConfig& cfg) {
  return where.empty() ? cfg.source : where;
}

// `pose[o]` / `size[a]`: an Index into the named collection by the given variable.
void expect_index(const rd::Call& call, const std::string& param, const std::string& collection,
                  const std::string& var) {
  const rd::Value& v = call.at(param);
  if (v.kind != rd::Value::Kind::Index || v.text != collection || v.items.size() != 1 ||
      v.items[0].kind != rd::Value::Kind::Name || v.items[0].text != var)
    fail(call.where, fmt::format("{}: parameter '{}' must be {}[{}]", call.name, param, collection, var));
}

void expect_name(const rd::Call& call, const std::string& param, const std::string& var) {
  const rd::Value& v = call.at(param);
  if (v.kind != rd::Value::Kind::Name || v.text != var)
    fail(call.where, fmt::format("{}: parameter '{}' must be the variable {}", call.name, param, var));
}

struct ExtractSpec {
  const char* call;
  std::size_t arity;
};

const std::map<std::string, ExtractSpec>& extract_specs() {
  static const std::map<std::string, ExtractSpec> specs = {
      {"stable", {"obb.stable", 1}},         {"table", {"scene.is_table", 1}},
      {"hover", {"obb.hover", 1}},           {"contact", {"obb.contact", 2}},
      {"intersect", {"obb.intersect", 2}},   {"higher", {"obb.higher", 2}},
  };
  return specs;
}

void read_model(const rd::DomainConfig& cfg) {
  bool pose = false, size = false;
  for (const auto& v : cfg.model) {
    if (v.name == "pose" && v.collection && v.index_type == "object" && v.value_type == "se3" && v.sampled) {
      pose = true;
    } else if (v.name == "size" && v.collection && v.index_type == "object" && v.value_type == "vec3" &&
               !v.sampled) {
      size = true;
    } else {
      fail(cfg.source, fmt::format("model variable '{}' ({}{}{}) is not implemented by the tabletop kit "
                                   "(it knows pose[object]: se3 sampled, size[object]: vec3 fixed)",
                                   v.name, v.value_type, v.collection ? " per " : "", v.index_type));
    }
  }
  if (!pose) fail(cfg.source, "the tabletop kit needs the model variable pose[object] : se3 sampled");
  if (!size) fail(cfg.source, "the tabletop kit needs the model variable size[object] : vec3 fixed");
}

void read_extracts(const rd::DomainConfig& cfg, KitConfig& out) {
  std::set<std::string> seen;
  double contact_eps = -1.0, intersect_eps = -1.0, stable_tol = -1.0;
  double vertical_contact_eps = out.evidence.vertical_contact_eps;
  double vertical_intersect_eps = out.evidence.vertical_intersect_eps;
  std::string hover_where;
  for (const auto& e : cfg.extract) {
    const auto it = extract_specs().find(e.predicate);
    const std::string where = place(e.call.where, cfg);
    if (it == extract_specs().end())
      fail(where, fmt::format("extract {}: the tabletop kit has no extractor for predicate '{}'", e.predicate,
                              e.predicate));
    if (e.call.name != it->second.call)
      fail(where, fmt::format("extract {}: unknown call '{}' (the tabletop kit implements {} for it)",
                              e.predicate, e.call.name, it->second.call));
    if (e.vars.size() != it->second.arity)
      fail(where, fmt::format("extract {}: expected {} variable(s), got {}", e.predicate, it->second.arity,
                              e.vars.size()));
    if (!seen.insert(e.predicate).second) fail(where, fmt::format("extract {}: given twice", e.predicate));
    const rd::Call& c = e.call;
    if (e.predicate == "stable") {
      expect_index(c, "pose", "pose", e.vars[0]);
      expect_index(c, "size", "size", e.vars[0]);
      stable_tol = c.positive("tol");
      if (stable_tol >= std::numbers::pi / 2) fail(where, "obb.stable: tol must be below 90 deg");
    } else if (e.predicate == "contact" || e.predicate == "intersect" || e.predicate == "higher") {
      expect_index(c, "pose_a", "pose", e.vars[0]);
      expect_index(c, "size_a", "size", e.vars[0]);
      expect_index(c, "pose_b", "pose", e.vars[1]);
      expect_index(c, "size_b", "size", e.vars[1]);
      if (e.predicate == "contact") contact_eps = c.positive("eps");
      if (e.predicate == "intersect") intersect_eps = c.positive("eps");
      // Optional (not yet in stdlib/tabletop.ksm): the tolerance for near-vertical gaps /
      // penetrations between stacked boxes and the table; stdlib default when absent.
      if (c.find("vertical_eps")) {
        if (e.predicate == "contact") vertical_contact_eps = c.positive("vertical_eps");
        if (e.predicate == "intersect") vertical_intersect_eps = c.positive("vertical_eps");
      }
    } else if (e.predicate == "hover") {
      expect_name(c, "o", e.vars[0]);
      out.hover_eps = c.positive("eps");
      hover_where = where;
    } else if (e.predicate == "table") {
      expect_name(c, "o", e.vars[0]);
    }
  }
  for (const auto& [pred, spec] : extract_specs())
    if (!seen.count(pred))
      fail(cfg.source, fmt::format("no extract for evidence predicate '{}' (the tabletop kit needs {}(...) = {})",
                                   pred, pred, spec.call));
  // hover(o) is "no contact and no intersection with any body" (stdlib/tabletop/extract_hover.h),
  // so it can only use the contact tolerance.
  if (std::abs(out.hover_eps - contact_eps) > 1e-12)
    fail(hover_where, fmt::format("obb.hover: eps ({} m) must equal obb.contact's eps ({} m): hover is "
                                  "derived from the contact relation",
                                  out.hover_eps, contact_eps));
  out.evidence.stable_tol_rad = stable_tol;
  out.evidence.contact_eps = contact_eps;
  out.evidence.intersect_eps = intersect_eps;
  out.evidence.vertical_contact_eps = std::max(vertical_contact_eps, contact_eps);
  out.evidence.vertical_intersect_eps = std::max(vertical_intersect_eps, intersect_eps);
}

void read_prior_likelihood(const rd::DomainConfig& cfg, KitConfig& out) {
  if (cfg.prior.empty()) fail(cfg.source, "the tabletop kit needs `prior mln;`");
  for (const auto& p : cfg.prior) {
    const std::string where = place(p.call.where, cfg);
    if (p.call.name != "mln") fail(where, fmt::format("prior: unknown call '{}' (the tabletop kit implements: mln)", p.call.name));
    if (!p.vars.empty() || !p.conditions.empty()) fail(where, "prior mln: takes no variables or conditions");
    if (!out.prior_where.empty()) fail(where, "prior mln: given twice");
    out.prior_where = where;
  }
  if (cfg.likelihood.size() != 1)
    fail(cfg.source, fmt::format("the tabletop kit needs exactly one likelihood, got {}", cfg.likelihood.size()));
  const rd::Call& c = cfg.likelihood[0];
  const std::string where = place(c.where, cfg);
  if (c.name != "keypoints.gaussian")
    fail(where, fmt::format("likelihood: unknown call '{}' (the tabletop kit implements: keypoints.gaussian)", c.name));
  out.likelihood.sigma_px = c.positive("sigma");
  out.likelihood.robust = c.flag("robust");
  out.likelihood.outlier_px = c.positive("outlier_px");
  out.likelihood_where = where;
}

void read_kernels(const rd::DomainConfig& cfg, KitConfig& out) {
  if (cfg.kernels.empty()) fail(cfg.source, "the tabletop kit needs at least one kernel");
  for (const auto& k : cfg.kernels) {
    const std::string where = place(k.where, cfg);
    if (k.sources.size() != 1)
      fail(where, fmt::format("kernel {}: the tabletop kit implements kernels with exactly one source", k.name));
    const rd::Call& c = k.sources[0];
    const std::string cwhere = place(c.where, cfg);
    if (c.name != "pose.perturb")
      fail(cwhere, fmt::format("kernel {}: unknown call '{}' (the tabletop kit implements: pose.perturb)", k.name,
                               c.name));
    if (k.params.size() != 1 || k.params[0].second != "object")
      fail(where, fmt::format("kernel {}: pose.perturb needs exactly one parameter of type object", k.name));
    if (k.reverse != k.name)
      fail(where, fmt::format("kernel {}: pose.perturb is symmetric and must be its own reverse (got '{}')",
                              k.name, k.reverse));
    expect_index(c, "pose", "pose", k.params[0].first);
    RefineKernelConfig r;
    r.name = k.name;
    r.reverse = k.reverse;
    r.sigma_t = c.positive("sigma_t");
    r.sigma_r = c.positive("sigma_r");
    const double n = c.positive("candidates");
    if (n != std::floor(n) || n > 100000) fail(cwhere, "pose.perturb: candidates must be an integer in [1, 100000]");
    r.candidates = static_cast<int>(n);
    r.where = where;
    out.kernels.push_back(std::move(r));
  }
}

void read_schedule(const rd::DomainConfig& cfg, KitConfig& out) {
  if (cfg.schedule.empty()) fail(cfg.source, "the tabletop kit needs a schedule");
  for (const auto& row : cfg.schedule) {
    if (row.begin < 0 || row.end <= row.begin)
      fail(cfg.source, fmt::format("schedule row [{}, {}): empty or negative range", row.begin, row.end));
    runtime::mcmc::ScheduleRow r;
    r.begin = static_cast<std::uint64_t>(row.begin);
    r.end = row.end == rd::ScheduleRow::kForever ? runtime::mcmc::kForever : static_cast<std::uint64_t>(row.end);
    for (const auto& [name, p] : row.probabilities) {
      const bool known = std::any_of(out.kernels.begin(), out.kernels.end(),
                                     [&](const RefineKernelConfig& k) { return k.name == name; });
      if (!known) fail(cfg.source, fmt::format("schedule: unknown kernel '{}'", name));
      r.probabilities.emplace_back(name, p);
    }
    out.schedule.push_back(std::move(r));
  }
}

}  // namespace

const std::vector<std::string>& implemented_calls() {
  static const std::vector<std::string> calls = {"obb.stable",  "obb.contact",    "obb.intersect",
                                                 "obb.higher",  "obb.hover",      "scene.is_table",
                                                 "mln",         "keypoints.gaussian", "pose.perturb"};
  return calls;
}

KitConfig read_kit_config(const rd::DomainConfig& config) {
  KitConfig out;
  out.domain = config.domain;
  out.source = config.source;
  read_model(config);
  read_extracts(config, out);
  read_prior_likelihood(config, out);
  read_kernels(config, out);
  read_schedule(config, out);
  return out;
}

}  // namespace ksmc::stdlib::tabletop::kit
