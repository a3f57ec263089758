// The generated grounding code of a domain (ksmc emit, compiled into this test) must build
// the same ground network as the runtime's generic grounder on the same program, for
// random evidence: same atoms, same blocks, same clauses with the same weights, the same
// folded constant, and the same error when a hard rule is unsatisfiable.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include KSMC_GENERATED_HEADER

namespace mln = ksmc::runtime::mln;
namespace gen = KSMC_GENERATED_NAMESPACE;

namespace {

using ClauseKey = std::tuple<std::vector<mln::Lit>, double, std::int32_t>;

std::vector<ClauseKey> clauses_of(const mln::GroundNetwork& net) {
  std::vector<ClauseKey> out;
  for (std::int32_t c = 0; c < net.num_clauses(); ++c) {
    auto lits = net.clause(c);
    out.emplace_back(std::vector<mln::Lit>(lits.begin(), lits.end()), net.weight(c), net.origin(c));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::vector<mln::AtomId>> blocks_of(const mln::GroundNetwork& net) {
  std::vector<std::vector<mln::AtomId>> out;
  for (std::int32_t b = 0; b < net.num_blocks(); ++b) {
    auto atoms = net.block(b);
    out.emplace_back(atoms.begin(), atoms.end());
  }
  return out;
}

}  // namespace

TEST_CASE("generated grounding equals the generic grounder on random evidence") {
  const mln::Program& program = gen::program();
  std::mt19937_64 rng(12345);
  int agreed_networks = 0;
  int agreed_errors = 0;
  for (int trial = 0; trial < 600; ++trial) {
    mln::Domain domain = gen::make_domain();
    const int n = 1 + trial % 5;
    for (std::size_t t = 0; t < program.types.size(); ++t) {
      if (domain.size(static_cast<std::int32_t>(t)) > 0) continue;  // enumerated
      for (int k = 0; k < n; ++k)
        domain.add(static_cast<std::int32_t>(t), program.types[t] + std::to_string(k));
    }
    mln::Evidence evidence(program, domain);
    const double p_true = (trial % 3 == 0) ? 0.0 : (trial % 3 == 1 ? 0.08 : 0.3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (std::size_t p = 0; p < program.predicates.size(); ++p) {
      const auto pi = static_cast<std::int32_t>(p);
      for (std::int64_t f = 0; f < evidence.num_atoms(pi); ++f) {
        if (!program.predicates[p].query) {
          evidence.set_flat(pi, f, u(rng) < p_true ? 1 : 0);
        } else if (u(rng) < 0.05) {
          evidence.set_flat(pi, f, u(rng) < 0.5 ? 1 : 0);  // a fixed query atom
        }
      }
    }
    std::string generic_error, generated_error;
    mln::Grounding a, b;
    try {
      a = mln::ground(program, domain, evidence);
    } catch (const mln::MlnError& e) {
      generic_error = e.what();
    }
    try {
      b = gen::ground(domain, evidence);
    } catch (const mln::MlnError& e) {
      generated_error = e.what();
    }
    INFO("trial " << trial << ", " << n << " constants per type");
    // Both name the same rule; the binding named may differ (the loops run in another order).
    auto rule_part = [](const std::string& e) { return e.substr(0, e.find(" for ")); };
    REQUIRE(rule_part(generic_error) == rule_part(generated_error));
    if (!generic_error.empty()) {
      ++agreed_errors;
      continue;
    }
    REQUIRE(a.network.num_atoms() == b.network.num_atoms());
    REQUIRE(a.index.atom == b.index.atom);
    REQUIRE(a.index.fixed == b.index.fixed);
    REQUIRE(blocks_of(a.network) == blocks_of(b.network));
    const auto ca = clauses_of(a.network);
    const auto cb = clauses_of(b.network);
    REQUIRE(ca.size() == cb.size());
    for (std::size_t i = 0; i < ca.size(); ++i) {
      REQUIRE(std::get<0>(ca[i]) == std::get<0>(cb[i]));
      REQUIRE(std::get<1>(ca[i]) == Approx(std::get<1>(cb[i])).epsilon(1e-12));
      REQUIRE(std::get<2>(ca[i]) == std::get<2>(cb[i]));
    }
    REQUIRE(a.network.constant() == Approx(b.network.constant()).epsilon(1e-9).margin(1e-9));
    ++agreed_networks;
  }
  WARN("networks compared: " << agreed_networks << ", unsatisfiable evidence compared: " << agreed_errors);
  CHECK(agreed_networks >= 100);
}
