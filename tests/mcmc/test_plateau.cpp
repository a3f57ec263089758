// The plateau criterion (runtime/mcmc/plateau.h): best(i + window) - best(i) <= min_gain.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "runtime/mcmc/plateau.h"

using namespace ksmc::runtime::mcmc;

TEST_CASE("plateau: strict criterion finds the first point with no gain over the window", "[mcmc]") {
  PlateauDetector d({100, 0.0});
  // best rises until iteration 300, then stays flat.
  bool hit = false;
  std::uint64_t at = 0;
  for (std::uint64_t it = 10; it <= 1000 && !hit; it += 10) {
    const double best = it <= 300 ? static_cast<double>(it) : 300.0;
    hit = d.observe(it, best, 0.001 * static_cast<double>(it));
    at = it;
  }
  REQUIRE(hit);
  REQUIRE(d.reached());
  CHECK(d.plateau()->iteration == 300);
  CHECK(d.plateau()->seconds == Approx(0.3));
  CHECK(d.detected()->iteration == 400);
  CHECK(at == 400);
  CHECK(d.observe(410, 300.0, 0.41));  // stays reached
  CHECK(d.plateau()->iteration == 300);
}

TEST_CASE("plateau: small gains count as none only up to min_gain", "[mcmc]") {
  // Gains of 0.5 every 50 iterations: 1.0 per 100-iteration window.
  auto run = [](double min_gain) {
    PlateauDetector d({100, min_gain});
    for (std::uint64_t it = 50; it <= 2000; it += 50)
      if (d.observe(it, 0.5 * static_cast<double>(it / 50), 0.0)) return d.plateau()->iteration;
    return std::uint64_t{0};
  };
  CHECK(run(0.0) == 0);   // never flat
  CHECK(run(0.99) == 0);  // 1.0 > 0.99
  CHECK(run(1.0) == 50);  // the first point already qualifies
}

TEST_CASE("plateau: irregular spacing judges each point against the first at or after i + window", "[mcmc]") {
  PlateauDetector d({100, 0.0});
  CHECK_FALSE(d.observe(1, 0.0, 0.0));
  CHECK_FALSE(d.observe(90, 5.0, 0.0));
  CHECK_FALSE(d.observe(150, 6.0, 0.0));  // judges 1: gain 6
  CHECK_FALSE(d.observe(195, 6.0, 0.0));  // 90 not yet judged (needs >= 190): gain 1 -> no
  CHECK(d.observe(260, 6.0, 0.0));        // judges 150: gain 0
  CHECK(d.plateau()->iteration == 150);
  CHECK(d.detected()->iteration == 260);
}

TEST_CASE("plateau: bad input is refused", "[mcmc]") {
  CHECK_THROWS_AS(PlateauDetector({0, 0.0}), std::invalid_argument);
  CHECK_THROWS_AS(PlateauDetector({10, -1.0}), std::invalid_argument);
  CHECK_THROWS_AS(PlateauDetector({10, NAN}), std::invalid_argument);
  PlateauDetector d({10, 0.0});
  d.observe(5, 1.0, 0.0);
  CHECK_THROWS_AS(d.observe(5, 1.0, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(d.observe(6, 0.5, 0.0), std::invalid_argument);
}
