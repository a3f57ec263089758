#include "compiler/infer/infer_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "compiler/infer/db_diagnostics.h"
#include "runtime/mln/components.h"
#include "runtime/mln/error.h"
#include "runtime/mln/exact.h"
#include "runtime/mln/ground_bound.h"
#include "runtime/mln/evidence.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/inference.h"
#include "runtime/mln/maxwalksat.h"

namespace ksmc::compiler::infer {
namespace {

namespace mln = ksmc::runtime::mln;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char ch : s) {
    if (ch == ',') {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur.push_back(ch);
    }
  }
  out.push_back(trim(cur));
  return out;
}

std::string format_probability(double p) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6f", p);
  return buf;
}

}  // namespace

std::string build_domain(const lower::MlnIr& ir, const std::string& text, const std::string& path,
                         mln::Domain& domain) {
  const auto& program = ir.program;
  domain.resize(program.types.size());
  for (std::size_t t = 0; t < ir.enumerated.size(); ++t)
    for (const auto& c : ir.enumerated[t]) domain.add(static_cast<std::int32_t>(t), c);

  // `type = {A, B, C}` lines declare constants; they are blanked before the atom parser runs
  // so that its line numbers stay right.
  std::istringstream in(text);
  std::ostringstream atoms;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    std::string code = line.substr(0, line.find("//"));
    const auto eq = code.find('=');
    if (eq != std::string::npos && code.find('{') != std::string::npos && code.find('(') == std::string::npos) {
      const std::string where = path + ":" + std::to_string(line_no) + ": ";
      const std::string type_name = trim(code.substr(0, eq));
      const auto type = program.find_type(type_name);
      if (!type) throw mln::MlnError(where + "unknown type '" + type_name + "'");
      const auto open = code.find('{');
      const auto close = code.rfind('}');
      if (close == std::string::npos || close < open)
        throw mln::MlnError(where + "malformed constant declaration: expected " + type_name + " = {A, B, ...}");
      for (const auto& c : split_list(code.substr(open + 1, close - open - 1))) {
        if (c.empty()) throw mln::MlnError(where + "empty constant name in declaration of '" + type_name + "'");
        const bool enumerated = !ir.enumerated[static_cast<std::size_t>(*type)].empty();
        if (enumerated && !domain.find(*type, c))
          throw mln::MlnError(where + "unknown constant '" + c + "' of enumerated type '" + type_name + "'");
        domain.add(*type, c);
      }
      atoms << "\n";
      continue;
    }
    atoms << line << "\n";
  }
  const std::string atom_text = atoms.str();

  // Constants named in atoms join their type, except for enumerated types, whose constants
  // are fixed by the domain file (an undeclared one is reported by parse_db_all, with a
  // suggestion, together with every other bad line).
  mln::Domain seen = domain;
  collect_constants_lenient(atom_text, path, program, seen);
  for (std::size_t t = 0; t < program.types.size(); ++t) {
    const auto ti = static_cast<std::int32_t>(t);
    if (!ir.enumerated[t].empty()) continue;
    for (const auto& c : seen.constants(ti)) domain.add(ti, c);
  }
  return atom_text;
}

std::int64_t parse_count(const std::string& text) {
  std::size_t used = 0;
  const long long v = std::stoll(text, &used);
  if (used != text.size() || v < 0) throw std::invalid_argument(text);
  return v;
}

namespace {

void print_error(const std::string& m, const std::string& path, std::ostream& err) {
  err << with_error_tag(m, path, "ksmc infer") << "\n";
}

}  // namespace

int run_infer(const lower::MlnIr& ir, const InferRequest& request, std::ostream& out, std::ostream& err) {
  const auto& program = ir.program;
  if (request.samples == 0) {
    err << "ksmc infer: --samples must be at least 1 (marginals from no samples are meaningless)\n";
    return 2;
  }
  if (request.max_ground_clauses == 0) {
    err << "ksmc infer: --max-ground-clauses must be at least 1\n";
    return 2;
  }
  if (request.max_ground_clauses > 0)
    runtime::mln::set_max_ground_clauses(static_cast<std::uint64_t>(request.max_ground_clauses));
  static const std::set<std::string> kMethods{"exact", "gibbs", "mcsat", "map", "auto"};
  if (!kMethods.count(request.method)) {
    err << "ksmc infer: unknown method '" << request.method << "' (exact, gibbs, mcsat, map or auto)\n";
    return 2;
  }
  std::vector<bool> wanted(program.predicates.size(), request.queries.empty());
  for (const auto& q : request.queries) {
    const auto p = program.find_predicate(q);
    if (!p || !program.predicates[static_cast<std::size_t>(*p)].query) {
      err << "ksmc infer: --query: '" << q << "' is not a query predicate of domain '" << ir.domain << "'\n";
      return 2;
    }
    wanted[static_cast<std::size_t>(*p)] = true;
  }
  std::error_code dir_ec;
  if (std::filesystem::is_directory(request.evidence_path, dir_ec)) {
    err << request.evidence_path << ": error: evidence file expected, this is a folder\n";
    return 1;
  }
  std::ifstream file(request.evidence_path, std::ios::binary);
  if (!file) {
    err << request.evidence_path << ": error: cannot read the evidence file\n";
    return 1;
  }
  std::stringstream buffer;
  buffer << file.rdbuf();

  try {
    mln::Domain domain;
    const std::string atoms = build_domain(ir, buffer.str(), request.evidence_path, domain);
    mln::Evidence evidence(program, domain);
    mln::DbOptions db_options;
    db_options.allow_all_query_evidence = true;  // partial observation: given query atoms are fixed
    const auto errors = parse_db_all(atoms, request.evidence_path, program, domain, evidence, db_options);
    for (const auto& e : errors) print_error(e, request.evidence_path, err);
    if (!errors.empty()) {
      if (errors.size() > 1) err << "ksmc infer: " << errors.size() << " errors in " << request.evidence_path << "\n";
      return 1;
    }
    const mln::Grounding g = mln::ground(program, domain, evidence);
    const auto& net = g.network;

    mln::InferenceResult result;
    std::string method = request.method;
    if (method == "map") {
      // Exact (enumeration or max-product elimination per component) when every component
      // fits; MaxWalkSAT otherwise.
      bool exact = true;
      for (const auto& comp : mln::split_components(net))
        exact = exact && mln::plan_exact(net, comp, {}).solver != mln::ExactPlan::Solver::TooLarge;
      mln::MapResult m;
      if (exact) {
        m = mln::exact_map(net);
      } else {
        mln::MapOptions o;
        o.seed = request.seed;
        m = mln::max_walksat(net, o);
        if (!m.feasible) throw mln::MlnError("MaxWalkSAT found no state satisfying every hard rule");
      }
      result.marginals.assign(m.state.begin(), m.state.end());
      method = exact ? "map (exact)" : "map (maxwalksat)";
    } else {
      mln::InferenceOptions o;
      o.method = mln::parse_method(method);
      o.gibbs.seed = o.mcsat.seed = o.log_z.seed = request.seed;
      if (request.burn_in >= 0) o.gibbs.burn_in = o.mcsat.burn_in = request.burn_in;
      if (request.samples >= 0) o.gibbs.samples = o.mcsat.samples = request.samples;
      result = mln::infer(net, o);
      method = result.method;
    }

    std::vector<std::string> lines;
    for (std::size_t p = 0; p < program.predicates.size(); ++p) {
      if (!program.predicates[p].query || program.predicates[p].auxiliary || !wanted[p]) continue;
      const std::int64_t n = evidence.num_atoms(static_cast<std::int32_t>(p));
      const std::int64_t off = g.index.offset[p];
      for (std::int64_t f = 0; f < n; ++f) {
        const double prob = g.marginal(result, off + f);
        lines.push_back(g.atom_name(off + f) + " " +
                        (request.method == "map" ? std::string(prob > 0.5 ? "1" : "0") : format_probability(prob)));
      }
    }
    std::sort(lines.begin(), lines.end());
    for (const auto& l : lines) out << l << "\n";
    if (!request.result_path.empty()) {  // Alchemy's .result: one `atom probability` line per query atom
      std::ofstream result_file(request.result_path, std::ios::binary);
      for (const auto& l : lines) result_file << l << "\n";
      if (!result_file) {
        err << "ksmc infer: error: cannot write the result file '" << request.result_path << "'\n";
        return 1;
      }
    }
    err << "ksmc infer: " << method << ", " << g.index.num_query_atoms << " query atoms (" << net.num_atoms()
        << " free), " << net.num_clauses() << " ground clauses";
    if (!std::isnan(result.log_z)) err << ", log Z " << (result.log_z_exact ? "= " : "~ ") << result.log_z;
    err << "\n";
    return 0;
  } catch (const mln::MlnError& e) {
    print_error(e.what(), request.evidence_path, err);
    return 1;
  }
}

}  // namespace ksmc::compiler::infer
