#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "runtime/mcmc/rng.h"
#include "stdlib/segments/scene.h"

using namespace ksmc::stdlib::segments;
using ksmc::runtime::mcmc::Rng;

namespace {

std::shared_ptr<const std::vector<Vec2>> random_points(Rng& rng, std::size_t n) {
  auto pts = std::make_shared<std::vector<Vec2>>();
  for (std::size_t i = 0; i < n; ++i) pts->push_back({rng.uniform(0.0, 3.0), rng.uniform(0.0, 2.0)});
  return pts;
}

Segment random_segment(Rng& rng) {
  return canonical({rng.uniform(0.0, 3.0), rng.uniform(0.0, 2.0)}, {rng.uniform(0.0, 3.0), rng.uniform(0.0, 2.0)});
}

}  // namespace

TEST_CASE("the point term is the robust Gaussian mixture", "[segments][scene]") {
  auto pts = std::make_shared<const std::vector<Vec2>>(std::vector<Vec2>{{0, 0}, {1, 0.1}});
  Scene s(pts, {0.05, 0.1});
  CHECK(s.term(0.0) == Approx(0.0).margin(1e-12));
  CHECK(s.term(0.05) == Approx(std::log(0.9 * std::exp(-0.5) + 0.1)));
  CHECK(s.term(std::numeric_limits<double>::infinity()) == Approx(std::log(0.1)));
  CHECK(s.log_likelihood() == Approx(2 * std::log(0.1)));  // no segment: background only
  const Segment add[1] = {{{0, 0}, {1, 0}}};
  s.change({}, add);
  CHECK(s.nearest(1) == 0);
  CHECK(s.distance(1) == Approx(0.1));
  CHECK(s.log_likelihood() == Approx(s.term(0.0) + s.term(0.1)));
  CHECK_THROWS(Scene(pts, {0.0, 0.1}));
  CHECK_THROWS(Scene(pts, {0.05, 1.0}));
}

TEST_CASE("incremental likelihood equals a full recompute over random moves", "[segments][scene]") {
  Rng rng(11);
  Scene s(random_points(rng, 300), {0.03, 0.05});
  for (int it = 0; it < 2000; ++it) {
    const std::size_t n = s.size();
    std::vector<std::size_t> remove;
    std::vector<Segment> add;
    const int kind = static_cast<int>(rng.uniform_int(4));
    if (kind == 0 || n == 0) {
      add.push_back(random_segment(rng));
    } else if (kind == 1) {
      remove.push_back(rng.uniform_int(n));
    } else if (kind == 2 && n >= 2) {
      const std::size_t i = rng.uniform_int(n);
      std::size_t j = rng.uniform_int(n - 1);
      if (j >= i) ++j;
      remove = {i, j};
      add.push_back(random_segment(rng));
    } else {
      remove.push_back(rng.uniform_int(n));
      add = {random_segment(rng), random_segment(rng)};
    }
    const double before = s.log_likelihood();
    const auto lines_before = s.lines();
    s.change(remove, add);
    REQUIRE(s.log_likelihood() == Approx(s.recompute_log_likelihood()).epsilon(1e-12).margin(1e-9));
    if (rng.bernoulli(0.4)) {
      s.rollback();
      REQUIRE(s.log_likelihood() == before);  // bit-identical
      REQUIRE(s.lines().size() == lines_before.size());
      for (std::size_t k = 0; k < lines_before.size(); ++k) REQUIRE(s.lines()[k].seg == lines_before[k].seg);
    } else {
      s.commit();
    }
    if (s.size() > 25) {
      s.change(std::vector<std::size_t>{0, 1, 2, 3, 4}, {});
      s.commit();
    }
  }
  // Nearest assignment agrees with a brute-force search.
  for (std::size_t i = 0; i < s.points().size(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (const Line& l : s.lines()) best = std::min(best, point_segment_distance(s.points()[i], l.seg));
    REQUIRE(s.distance(i) == Approx(best));
  }
}

TEST_CASE("reset and ids", "[segments][scene]") {
  Rng rng(3);
  Scene s(random_points(rng, 50), {0.03, 0.05});
  const Segment add[2] = {random_segment(rng), random_segment(rng)};
  const std::uint64_t ids[2] = {7, 9};
  s.change({}, add, ids);
  s.commit();
  CHECK(s.lines()[0].id == 7);
  CHECK(s.lines()[1].id == 9);
  const double ll = s.log_likelihood();
  Scene t(std::make_shared<const std::vector<Vec2>>(s.points()), {0.03, 0.05});
  t.reset(s.lines(), 0);
  CHECK(t.next_id() == 10);
  CHECK(t.log_likelihood() == Approx(ll));
  CHECK_THROWS(s.change(std::vector<std::size_t>{5}, {}));
}
