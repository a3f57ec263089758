#include <catch2/catch.hpp>

#include <cmath>

#include "kit_fixture.h"
#include "runtime/mcmc/rng.h"

using namespace ksmc::stdlib::segments;
using namespace ksmc::stdlib::segments::kit;
using ksmc::runtime::mcmc::Rng;

namespace {

// The tests know the example's predicates by name; the kit never does.
std::size_t pred(const Semantics& s, const std::string& name) {
  return static_cast<std::size_t>(*s.core().program().find_predicate(name));
}

}  // namespace

TEST_CASE("Markov logic semantics: corners, walls, cache, mln prior", "[segments][kit]") {
  const auto sh = segments_test::room_input();
  SegmentsModel m(sh);
  CHECK(m.log_prior() == 0.0);  // no line: no term
  // Lines 0/1 meet at a right angle; 2 continues 0 across a door gap.
  const Segment add[3] = {{{0, 0}, {2, 0}}, {{0, 0.05}, {0, 4}}, {{2.9, 0}, {6, 0}}};
  m.change({}, add);
  m.accept();
  const auto o = m.outcome();
  const Semantics& sem = m.semantics();
  const std::size_t n = 3;
  CHECK(o->values[pred(sem, "touching")][0 * n + 1] == 1.0);
  CHECK(o->values[pred(sem, "touching")][0 * n + 0] == 0.0);  // never with itself
  CHECK(o->values[pred(sem, "Corner")][0 * n + 1] > 0.9);
  CHECK(o->values[pred(sem, "Corner")][1 * n + 0] > 0.9);
  CHECK(o->values[pred(sem, "Corner")][0 * n + 2] == Approx(0.0).margin(1e-12));
  CHECK(o->values[pred(sem, "SameWall")][0 * n + 2] > 0.9);
  CHECK(o->values[pred(sem, "SameWall")][0 * n + 1] == Approx(0.0).margin(1e-12));
  CHECK(std::isfinite(m.prior_parts().mln));
  CHECK(m.prior_parts().semantic < 0.0);  // the corner's 5 cm gap costs a little
  // A short isolated line is more likely spurious than the others (odds 4 : 9 under the
  // rules short => Spurious (p 0.8) and !Spurious (p 0.9)); the prior mln term drops.
  const double mln_before = m.prior_parts().mln;
  const Segment clutter[1] = {{{3, 2}, {3.2, 2.1}}};
  m.change({}, clutter);
  const auto& spurious = m.outcome()->values[pred(sem, "Spurious")];
  CHECK(spurious[3] == Approx(4.0 / 13.0).epsilon(1e-6));
  CHECK(spurious[0] < 0.05);
  CHECK(m.prior_parts().mln < mln_before);
  m.reject();
  CHECK(m.prior_parts().mln == mln_before);
  // Re-evaluating the same evidence hits the cache.
  const auto runs = m.semantics().core().stats().inferences;
  m.change({}, clutter);
  m.reject();
  CHECK(m.semantics().core().stats().inferences == runs);
}

TEST_CASE("incremental posterior equals a full recompute over kernel moves", "[segments][kit]") {
  const auto sh = segments_test::room_input();
  SegmentsModel m(sh);
  Rng rng(5);
  using Fn = ksmc::runtime::mcmc::Proposal (*)(SegmentsModel&, Rng&);
  const Fn moves[5] = {segments_test::birth, segments_test::death, segments_test::split, segments_test::merge, segments_test::jitter};
  int made = 0;
  for (int it = 0; it < 600; ++it) {
    const double before = m.log_posterior();
    const auto p = moves[it < 60 ? 0 : rng.uniform_int(5)](m, rng);
    if (p.was_declined()) {
      REQUIRE(m.log_posterior() == before);
      continue;
    }
    ++made;
    REQUIRE(std::isfinite(p.log_q_fwd));
    const double tentative = m.log_posterior();
    if (std::isfinite(tentative)) REQUIRE(tentative == Approx(m.recompute_log_posterior()).margin(1e-8));
    if (rng.bernoulli(0.5)) {
      m.accept();
    } else {
      m.reject();
      REQUIRE(m.log_posterior() == before);
    }
  }
  CHECK(made > 300);
  // Snapshot round trip.
  SegmentsModel copy(sh);
  copy.restore(m.snapshot());
  CHECK(copy.log_posterior() == Approx(m.log_posterior()).margin(1e-8));
  CHECK(copy.snapshot() == m.snapshot());
}
