#include "compiler/learn/learn_command.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "compiler/infer/db_diagnostics.h"
#include "compiler/infer/infer_command.h"
#include "runtime/mln/error.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/weight_learning.h"

namespace ksmc::compiler::learn {
namespace {

namespace mln = ksmc::runtime::mln;

std::string read_file(const std::string& path, bool& ok) {
  std::ifstream in(path, std::ios::binary);
  ok = static_cast<bool>(in);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string format(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  std::string s = buf;
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (s.back() == '.') s += '0';
  return s;
}

// A learned log-odds weight as the probability of a `prob p:` rule: 4 decimals, or as
// many more (up to 12) as it takes for the file's log-odds to be within 1e-3 of the
// learned weight (a weight of 12 is p = 0.999994, not 0.9999 = weight 9.2).
std::string probability_text(double w) {
  const double p = std::clamp(1.0 / (1.0 + std::exp(-w)), 1e-12, 1.0 - 1e-12);
  std::string text;
  for (int digits = 4; digits <= 12; ++digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, p);
    text = buf;
    const double q = std::strtod(buf, nullptr);
    if (q > 0.0 && q < 1.0 && std::abs(std::log(q / (1.0 - q)) - w) < 1e-3) break;
  }
  while (text.size() > 1 && text.back() == '0') text.pop_back();
  if (text.back() == '.') text += '0';
  return text;
}

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Offset of the weight spelling of a `w x:` / `prob x:` rule head at or after `from`.
std::size_t find_weight(const std::string& src, std::size_t from, const std::string& keyword, const std::string& spelling) {
  for (std::size_t at = src.find(keyword, from); at != std::string::npos; at = src.find(keyword, at + 1)) {
    if (at > 0 && ident_char(src[at - 1])) continue;
    std::size_t k = at + keyword.size();
    if (k >= src.size() || !std::isspace(static_cast<unsigned char>(src[k]))) continue;
    while (k < src.size() && std::isspace(static_cast<unsigned char>(src[k]))) ++k;
    if (src.compare(k, spelling.size(), spelling) == 0) return k;
  }
  return std::string::npos;
}

// A query atom the hard rules force given the evidence (fold_forced_atoms, or a folded
// block) but which the world has the other way: "Sa(A, B) true, but the hard rules and
// the evidence force it false". Empty when there is none.
std::string contradicted_forced_atom(const mln::Grounding& g, const mln::Evidence& world) {
  const auto& ix = g.index;
  for (std::size_t p = 0; p < ix.offset.size(); ++p) {
    if (ix.offset[p] < 0 || g.program->predicates[p].auxiliary) continue;
    for (std::int64_t f = 0; f < world.num_atoms(static_cast<std::int32_t>(p)); ++f) {
      const std::int64_t q = ix.offset[p] + f;
      if (ix.atom[q] >= 0 || ix.fixed[q] < 0) continue;
      const bool value = world.get_flat(static_cast<std::int32_t>(p), f) == 1;
      if (value == (ix.fixed[q] == 1)) continue;
      return g.atom_name(q) + (value ? " true" : " false") + ", but the hard rules and the evidence force it " +
             (value ? "false" : "true");
    }
  }
  return {};
}

// The value of each auxiliary atom (per-formula weights: holds[F](v), equivalent to F by
// the hard clauses) in the world: the one of its two values that satisfies them.
void set_auxiliary_atoms(const mln::Grounding& g, std::vector<std::uint8_t>& world) {
  const auto& net = g.network;
  const auto& preds = g.program->predicates;
  const mln::Occurrences occ = mln::build_occurrences(net);
  for (mln::AtomId a = 0; a < net.num_atoms(); ++a) {
    if (!preds[static_cast<std::size_t>(net.label(a))].auxiliary) continue;
    world[a] = 0;
    for (std::int32_t c : occ.clauses_of(a)) {
      if (!net.is_hard(c)) continue;
      bool sat = false;
      for (mln::Lit l : net.clause(c)) sat = sat || mln::lit_true(l, world[mln::lit_atom(l)]);
      if (!sat) {
        world[a] = 1;
        break;
      }
    }
  }
}

}  // namespace

std::string replace_weights(const std::string& source, const std::vector<lower::RuleIr>& rules,
                            const std::vector<std::string>& replacement) {
  std::vector<std::size_t> line_start{0};
  for (std::size_t i = 0; i < source.size(); ++i)
    if (source[i] == '\n') line_start.push_back(i + 1);
  std::vector<std::pair<std::size_t, std::size_t>> edits;  // (offset, rule)
  for (std::size_t r = 0; r < rules.size(); ++r) {
    if (replacement[r].empty()) continue;
    const auto& rule = rules[r];
    if (rule.line < 1 || static_cast<std::size_t>(rule.line) > line_start.size()) continue;
    const std::string keyword = rule.kind == lower::RuleIr::WeightKind::Prob ? "prob" : "w";
    const std::size_t at = find_weight(source, line_start[rule.line - 1], keyword, rule.written);
    if (at != std::string::npos) edits.push_back({at, r});
  }
  std::string out = source;
  std::sort(edits.begin(), edits.end());
  for (auto it = edits.rbegin(); it != edits.rend(); ++it)
    out.replace(it->first, rules[it->second].written.size(), replacement[it->second]);
  return out;
}

int run_learn(const lower::MlnIr& ir, const std::string& ksm_path, const std::vector<std::string>& data,
              const LearnRequest& request, std::ostream& out, std::ostream& err) {
  if (request.method != "pll" && request.method != "cll") {
    err << "ksmc learn: unknown method '" << request.method << "' (pll or cll)\n";
    return 2;
  }
  if (data.empty()) {
    err << "ksmc learn: give the training worlds: ksmc learn FILE.ksm --data a.db [b.db ...]\n";
    return 2;
  }
  if (request.per_formula && request.method != "cll") {
    err << "ksmc learn: --per-formula needs --method cll (the pseudo-likelihood would hold each formula's "
           "auxiliary atom fixed while it varies one atom)\n";
    return 2;
  }
  if (request.expectations != "auto" && request.expectations != "exact" && request.expectations != "sampled") {
    err << "ksmc learn: unknown --expectations '" << request.expectations << "' (auto, exact or sampled)\n";
    return 2;
  }
  if ((request.expectations != "auto" || request.samples >= 0) && request.method != "cll") {
    err << "ksmc learn: --expectations and --samples need --method cll (the pseudo-likelihood needs no inference)\n";
    return 2;
  }
  if (request.samples == 0) {
    err << "ksmc learn: --samples must be at least 1\n";
    return 2;
  }
  if (!(request.prior_sigma > 0.0)) {
    err << "ksmc learn: --l2 must be a positive standard deviation\n";
    return 2;
  }
  const auto& program = ir.program;
  // Parameters: the soft rules of the main file, tied over their CNF clauses.
  mln::WeightTying tying;
  tying.param_of_clause.assign(program.clauses.size(), -1);
  tying.scale_of_clause.assign(program.clauses.size(), 0.0);
  std::vector<int> param_rule;
  std::vector<double> initial;
  for (std::size_t r = 0; r < ir.rules.size(); ++r) {
    const auto& rule = ir.rules[r];
    if (rule.kind == lower::RuleIr::WeightKind::Hard || rule.group >= 0 || rule.clauses.empty() || rule.file != ksm_path)
      continue;
    for (int c : rule.clauses) {
      tying.param_of_clause[static_cast<std::size_t>(c)] = tying.num_params;
      tying.scale_of_clause[static_cast<std::size_t>(c)] = 1.0 / static_cast<double>(rule.clauses.size());
    }
    param_rule.push_back(static_cast<int>(r));
    initial.push_back(rule.weight);
    ++tying.num_params;
  }
  if (tying.num_params == 0) {
    err << ksm_path << ": error: no soft rule to learn\n";
    return 1;
  }
  std::vector<mln::TrainingSet> sets;
  std::vector<std::unique_ptr<mln::Domain>> domains;
  int bad_files = 0;
  std::int64_t worlds = 0;
  for (const auto& path : data) {
    bool ok = false;
    const std::string text = read_file(path, ok);
    if (!ok) {
      err << path << ": error: cannot read the training file\n";
      ++bad_files;
      continue;
    }
    try {
      auto domain = std::make_unique<mln::Domain>();
      const std::string atoms = infer::build_domain(ir, text, path, *domain);
      mln::Evidence full(program, *domain);
      mln::DbOptions all;
      all.allow_all_query_evidence = true;
      const auto errors = infer::parse_db_all(atoms, path, program, *domain, full, all);
      for (const auto& e : errors) err << infer::with_error_tag(e, path, "ksmc learn") << "\n";
      if (!errors.empty()) {
        ++bad_files;
        continue;
      }
      mln::Evidence given = full;  // query atoms become free; their values are the world
      for (std::size_t p = 0; p < program.predicates.size(); ++p) {
        if (!program.predicates[p].query) continue;
        for (std::int64_t f = 0; f < full.num_atoms(static_cast<std::int32_t>(p)); ++f)
          given.set_flat(static_cast<std::int32_t>(p), f, mln::Evidence::kUnknown);
      }
      mln::Grounding g = mln::ground(program, *domain, given);
      const std::string forced = contradicted_forced_atom(g, full);
      if (!forced.empty()) {
        err << path << ": error: the world has " << forced << "\n";
        ++bad_files;
        continue;
      }
      mln::TrainingSet ts;
      std::vector<std::uint8_t> world(static_cast<std::size_t>(g.network.num_atoms()), 0);
      for (mln::AtomId a = 0; a < g.network.num_atoms(); ++a) {
        const std::int64_t q = g.index.query_of_atom[a];
        std::int32_t p = 0;
        for (std::size_t i = 0; i < g.index.offset.size(); ++i)
          if (g.index.offset[i] >= 0 && g.index.offset[i] <= q) p = static_cast<std::int32_t>(i);
        world[a] = full.get_flat(p, q - g.index.offset[p]) == 1 ? 1 : 0;
      }
      set_auxiliary_atoms(g, world);
      ts.network = std::move(g.network);
      ts.worlds.push_back(std::move(world));
      sets.push_back(std::move(ts));
      domains.push_back(std::move(domain));
      ++worlds;
    } catch (const mln::MlnError& e) {
      err << infer::with_error_tag(e.what(), path, "ksmc learn: " + path) << "\n";
      ++bad_files;
    }
  }
  if (bad_files > 0) return 1;
  mln::LearnOptions options;
  options.objective = request.method == "cll" ? mln::Objective::ConditionalLikelihood : mln::Objective::PseudoLikelihood;
  options.prior_sigma = request.prior_sigma;
  options.expectations = request.expectations == "exact"     ? mln::Expectations::Exact
                         : request.expectations == "sampled" ? mln::Expectations::Sampled
                                                             : mln::Expectations::Auto;
  if (request.samples > 0) options.samples = request.samples;
  options.seed = request.seed;
  mln::LearnResult result;
  try {
    result = mln::learn_weights(sets, tying, initial, options);
  } catch (const mln::MlnError& e) {
    err << "ksmc learn: error: " << e.what() << "\n";
    return 1;
  }
  if (options.objective == mln::Objective::ConditionalLikelihood) {
    err << "ksmc learn: cll: " << result.gradient;
    if (result.too_large_set >= 0)
      err << ": the network of " << data[static_cast<std::size_t>(result.too_large_set)] << " has "
          << result.too_large_reason;
    else if (result.sampled)
      err << ": forced by --expectations sampled";
    err << "\n";
  }
  bool ok = false;
  const std::string source = read_file(ksm_path, ok);
  if (!ok) {
    err << ksm_path << ": error: cannot read the rule base again\n";
    return 1;
  }
  std::vector<std::string> replacement(ir.rules.size());
  for (std::size_t j = 0; j < param_rule.size(); ++j) {
    const auto& rule = ir.rules[static_cast<std::size_t>(param_rule[j])];
    const double w = result.params[j];
    if (rule.kind == lower::RuleIr::WeightKind::Prob) {
      replacement[static_cast<std::size_t>(param_rule[j])] = probability_text(w);
    } else {
      replacement[static_cast<std::size_t>(param_rule[j])] = format(w);
    }
    err << "ksmc learn: " << rule.name << " (" << rule.file << ":" << rule.line << "): "
        << (rule.kind == lower::RuleIr::WeightKind::Prob ? "prob " : "w ") << rule.written << " -> "
        << replacement[static_cast<std::size_t>(param_rule[j])] << "\n";
  }
  err << "ksmc learn: " << request.method << ", " << worlds << " training world" << (worlds == 1 ? "" : "s") << ", "
      << tying.num_params << " weight" << (tying.num_params == 1 ? "" : "s") << ", "
      << (result.sampled ? "stochastic, fixed" : result.converged ? "converged after" : "NOT converged after") << " "
      << result.iterations << " iterations\n";
  const std::string text = replace_weights(source, ir.rules, replacement);
  if (request.out_path.empty()) {
    out << text;
    return 0;
  }
  std::ofstream file(request.out_path, std::ios::binary);
  file << text;
  if (!file) {
    err << "ksmc learn: cannot write '" << request.out_path << "'\n";
    return 1;
  }
  return 0;
}

}  // namespace ksmc::compiler::learn
