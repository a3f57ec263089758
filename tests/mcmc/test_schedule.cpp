// (e) Schedule validation and kernel picking; RNG and alias-table basics.
#include <catch2/catch.hpp>

#include <map>
#include <string>

#include "runtime/mcmc/alias_table.h"
#include "runtime/mcmc/rng.h"
#include "runtime/mcmc/schedule.h"

namespace rm = ksmc::runtime::mcmc;

namespace {

std::vector<rm::KernelInfo> indoor_kernels() {
  return {{"ADD", "REMOVE"},      {"REMOVE", "ADD"},  {"SPLIT", "MERGE"}, {"MERGE", "SPLIT"},
          {"SHRINK", "DILATE"},   {"DILATE", "SHRINK"}, {"INTERCHANGE", "INTERCHANGE"},
          {"ALLOCATE", "DELETE"}, {"DELETE", "ALLOCATE"}};
}

rm::ScheduleRow row(std::uint64_t b, std::uint64_t e, std::vector<std::pair<std::string, double>> p) {
  return rm::ScheduleRow{b, e, std::move(p)};
}

// A Table 3.2-like schedule (the dissertation's exact numbers were lost in the text).
std::vector<rm::ScheduleRow> table_3_2() {
  return {row(0, 1000, {{"ADD", 0.8}, {"REMOVE", 0.2}}),
          row(1000, 4000, {{"ADD", 0.05}, {"REMOVE", 0.15}, {"SPLIT", 0.15}, {"MERGE", 0.15},
                           {"SHRINK", 0.15}, {"DILATE", 0.15}, {"INTERCHANGE", 0.2}}),
          row(4000, rm::kForever, {{"ADD", 0.05}, {"REMOVE", 0.1}, {"SPLIT", 0.1}, {"MERGE", 0.1},
                                   {"SHRINK", 0.1}, {"DILATE", 0.1}, {"INTERCHANGE", 0.15},
                                   {"ALLOCATE", 0.15}, {"DELETE", 0.15}})};
}

void expect_error(std::vector<rm::KernelInfo> k, std::vector<rm::ScheduleRow> rows, const std::string& what) {
  try {
    rm::Schedule s(std::move(k), std::move(rows));
    FAIL("expected ScheduleError containing: " << what);
  } catch (const rm::ScheduleError& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).find(what) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("a valid three-row schedule: rows, selection ratios, picks") {
  const rm::Schedule s(indoor_kernels(), table_3_2());
  CHECK(s.row_count() == 3);
  CHECK(s.row_index(0) == 0);
  CHECK(s.row_index(999) == 0);
  CHECK(s.row_index(1000) == 1);
  CHECK(s.row_index(3999) == 1);
  CHECK(s.row_index(4000) == 2);
  CHECK(s.row_index(1'000'000'000) == 2);
  CHECK(s.probability(1, 0) == 0.05);
  CHECK(s.log_selection_ratio(1, 0) == Approx(std::log(0.15 / 0.05)));
  CHECK(s.log_selection_ratio(1, 6) == 0.0);  // INTERCHANGE is its own reverse
  CHECK(s.reverse_of(2) == 3);

  rm::Rng rng(9);
  std::map<std::size_t, int> counts;
  const int n = 200000;
  for (int i = 0; i < n; ++i) ++counts[s.pick(2, rng)];
  for (std::size_t k = 0; k < s.kernel_count(); ++k) {
    CHECK(static_cast<double>(counts[k]) / n == Approx(s.probability(2, k)).margin(0.005));
  }
  counts.clear();
  for (int i = 0; i < 10000; ++i) ++counts[s.pick(0, rng)];
  CHECK(counts.size() == 2);  // zero-probability kernels are never picked
}

TEST_CASE("schedule validation errors name the problem") {
  const auto k = indoor_kernels();
  expect_error(k, {}, "no rows");
  expect_error(k, {row(0, 1000, {{"ADD", 0.5}, {"REMOVE", 0.4}}), row(1000, rm::kForever, {{"ADD", 0.5}, {"REMOVE", 0.5}})},
               "row 1 [0, 1000): probabilities sum to 0.9");
  expect_error(k, {row(0, 1000, {{"ADD", 0.5}, {"REMOVE", 0.5}}), row(1200, rm::kForever, {{"ADD", 0.5}, {"REMOVE", 0.5}})},
               "rows must be contiguous");
  expect_error(k, {row(5, rm::kForever, {{"ADD", 0.5}, {"REMOVE", 0.5}})}, "must start at iteration 0");
  expect_error(k, {row(0, 1000, {{"ADD", 0.5}, {"REMOVE", 0.5}})}, "must be open-ended");
  expect_error(k, {row(0, rm::kForever, {{"ADD", 0.5}, {"JUMP", 0.5}})}, "unknown kernel 'JUMP'");
  expect_error(k, {row(0, rm::kForever, {{"ADD", 1.5}, {"REMOVE", -0.5}})}, "not in [0, 1]");
  expect_error(k, {row(0, rm::kForever, {{"ADD", 0.5}, {"ADD", 0.5}})}, "listed twice");
  expect_error(k, {row(0, rm::kForever, {{"ADD", 0.5}, {"SPLIT", 0.5}})},
               "kernel 'ADD' has probability 0.5 but its reverse 'REMOVE' has 0");
  expect_error(k, {row(0, 0, {{"ADD", 0.5}, {"REMOVE", 0.5}}), row(0, rm::kForever, {{"ADD", 0.5}, {"REMOVE", 0.5}})},
               "empty iteration range");
  expect_error({{"ADD", "REMOVE"}}, {row(0, rm::kForever, {{"ADD", 1.0}})},
               "names reverse 'REMOVE', which is not a kernel");
  expect_error({{"A", "B"}, {"B", "C"}, {"C", "C"}}, {row(0, rm::kForever, {{"C", 1.0}})},
               "pairs must match");
  expect_error({{"A", "A"}, {"A", "A"}}, {row(0, rm::kForever, {{"A", 1.0}})}, "declared twice");
  expect_error({}, {row(0, rm::kForever, {})}, "no kernels");
}

TEST_CASE("alias table draws match the weights") {
  const std::vector<double> w = {0.0, 1.0, 3.0, 0.0, 6.0};
  const rm::AliasTable t(w);
  rm::Rng rng(11);
  std::vector<int> c(w.size(), 0);
  const int n = 100000;
  for (int i = 0; i < n; ++i) ++c[t.sample(rng)];
  CHECK(c[0] == 0);
  CHECK(c[3] == 0);
  CHECK(c[1] / double(n) == Approx(0.1).margin(0.005));
  CHECK(c[2] / double(n) == Approx(0.3).margin(0.006));
  CHECK(c[4] / double(n) == Approx(0.6).margin(0.006));
}

TEST_CASE("rng: reproducible, chain streams differ, distributions sane") {
  rm::Rng a(5);
  rm::Rng b(5);
  for (int i = 0; i < 100; ++i) CHECK(a.next() == b.next());
  const rm::Rng c0 = rm::Rng::for_chain(5, 0);
  rm::Rng c1 = rm::Rng::for_chain(5, 1);
  CHECK(c0 == rm::Rng(5));
  CHECK_FALSE(c1 == rm::Rng(5));
  rm::Rng r(77);
  double sum = 0.0;
  double sq = 0.0;
  std::vector<int> bins(7, 0);
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    const double z = r.normal();
    sum += z;
    sq += z * z;
    ++bins[r.uniform_int(7)];
  }
  CHECK(sum / n == Approx(0.0).margin(0.01));
  CHECK(sq / n == Approx(1.0).margin(0.02));
  for (int k : bins) CHECK(k / double(n) == Approx(1.0 / 7).margin(0.005));
  // Known first output of xoshiro256** seeded by splitmix64(0): pins the stream.
  rm::Rng zero(0);
  CHECK(zero.next() == 0x99EC5F36CB75F2B4ULL);
}
