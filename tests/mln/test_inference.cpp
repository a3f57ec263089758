// The infer() dispatcher (auto mode) and the AIS estimate of log Z against exact.
#include <catch2/catch.hpp>

#include <cstdio>
#include <sstream>

#include "runtime/mln/error.h"
#include "runtime/mln/grounder.h"
#include "runtime/mln/inference.h"
#include "tests/mln/network_fixtures.h"
#include "tests/mln/tabletop_kb.h"

using namespace ksmc::runtime::mln;

namespace {

GroundNetwork chain(std::int32_t n) {
  GroundNetwork net;
  net.set_label_names({"chain"});
  net.add_atoms(n, 0);
  for (AtomId a = 0; a + 1 < n; ++a) {
    const Lit imp[] = {make_lit(a, true), make_lit(a + 1, false)};
    net.add_clause(imp, 0.9);
    const Lit unit[] = {make_lit(a, a % 3 == 0)};
    net.add_clause(unit, 0.4);
  }
  const Lit h[] = {make_lit(0, false), make_lit(n - 1, false)};
  net.add_hard_clause(h);
  net.add_constant(1.5);
  return net;
}

GroundNetwork scene7() {
  static ksmc::tests::mln::TabletopKb kb;
  const std::string path = std::string(KSMC_SOURCE_DIR) + "/tests/mln/data/scene7.db";
  const auto text = read_text_file(path);
  static Domain d;
  collect_db_constants(text, path, kb.program, d);
  Evidence ev(kb.program, d);
  parse_db(text, path, kb.program, d, ev);
  return ground(kb.program, d, ev).network;
}

}  // namespace

TEST_CASE("AIS log Z estimate agrees with exact log Z", "[mln][logz]") {
  std::ostringstream table;
  table << "network        exact_logZ   ais_logZ  std_err  |diff|\n";
  const std::pair<const char*, GroundNetwork> cases[] = {
      {"mixed", ksmc::tests::mln::mixed_network()}, {"chain16", chain(16)}, {"tabletop7", scene7()}};
  for (const auto& [name, net] : cases) {
    INFO(name);
    LogZOptions exact_opt;
    const auto ex = log_partition(net, exact_opt);
    REQUIRE(ex.exact);
    LogZOptions ais_opt;
    ais_opt.force_ais = true;
    ais_opt.seed = 7;
    const auto est = log_partition(net, ais_opt);
    CHECK_FALSE(est.exact);
    const double diff = std::abs(est.log_z - ex.log_z);
    CHECK(diff < 0.05 + 3 * est.std_error);
    CHECK(est.std_error < 0.1);  // tabletop7: ~20 estimated components add up
    char line[128];
    std::snprintf(line, sizeof line, "%-12s %11.5f %10.5f %8.4f %7.4f\n", name, ex.log_z, est.log_z, est.std_error,
                  diff);
    table << line;
    // exact_inference's log Z is the same quantity
    CHECK(exact_inference(net).log_z == Approx(ex.log_z).margin(1e-9));
  }
  WARN(table.str());
}

TEST_CASE("auto mode: exact where possible, MC-SAT + AIS on large components", "[mln][auto]") {
  const auto net = chain(16);
  ExactOptions enum_only;
  enum_only.use_elimination = false;
  const auto truth = exact_inference(net, enum_only);
  InferenceOptions opt;
  opt.method = Method::Auto;
  opt.exact.max_component_bits = 10;
  opt.exact.use_elimination = false;  // a chain is easy for elimination: force sampling
  opt.mcsat.samples = 40000;
  const auto r = infer(net, opt);
  CHECK(r.method == "auto:mcsat 1");
  CHECK_FALSE(r.log_z_exact);
  for (std::size_t a = 0; a < r.marginals.size(); ++a) CHECK(std::abs(r.marginals[a] - truth.marginals[a]) < 0.02);
  CHECK(std::abs(r.log_z - truth.log_z) < 0.1);

  opt.exact.max_component_bits = 24;
  const auto r2 = infer(net, opt);
  CHECK(r2.method == "exact:enum 1");
  CHECK(r2.log_z_exact);
  CHECK(r2.marginals == truth.marginals);

  opt.method = Method::Exact;
  opt.exact.max_component_bits = 10;
  CHECK_THROWS_WITH(infer(net, opt), Catch::Contains("a connected component has 16 free atoms"));
  CHECK(parse_method("mcsat") == Method::McSat);
  CHECK_THROWS_WITH(parse_method("bp"), "unknown inference method 'bp' (expected exact, gibbs, mcsat or auto)");
}
