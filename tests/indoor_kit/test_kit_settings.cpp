// Reading the indoor DomainConfig: the fixture (= domains/indoor.ksm) gives the .ksm's values
// in base units; anything the kit does not implement is a ConfigError naming file:line.
#include <catch2/catch.hpp>

#include "stdlib/indoor/kit/settings.h"
#include "tests/indoor_kit/config_fixture.h"

using namespace ksmc::stdlib::indoor::kit;
using ksmc::runtime::domain::ConfigError;
namespace rd = ksmc::runtime::domain;

TEST_CASE("the indoor.ksm config reads into the kit's settings", "[indoor_kit]") {
  const IndoorSettings s = read_settings(ksmc::tests::indoor_kit::indoor_config());
  CHECK(s.semantic.enabled);
  CHECK(s.semantic.classifier.big_size_m == 10.0);
  CHECK(s.semantic.classifier.big_ratio == 3.0);
  CHECK(s.semantic.adjacent_dilate_cells == 2.0);
  CHECK(s.semantic.multi_door_min == 2);
  CHECK(s.semantic.sale_prior);
  CHECK(s.semantic.sale_predicate == "SaLe");
  CHECK(s.semantic.sale_threshold == 0.5);
  CHECK(s.semantic.sale_sigma_m == 0.3);
  CHECK(s.semantic.lenient_types == std::vector<std::string>{"Room", "Hall"});
  CHECK(s.lut[0][0] == 0.8);
  CHECK(s.lenient_lut[0][1] == 0.3);
  CHECK(s.lenient_lut[2][1] == 0.3);
  CHECK(s.psi1 == 1.0);
  CHECK(s.tol_rad == Approx(5.0 * 3.14159265358979323846 / 180.0));
  CHECK(s.psi2 == 1.0);
  CHECK(s.sources.wbu);
  CHECK(s.sources.wbu_min_size_m == 1.5);
  CHECK(s.sources.wbu_max_units == 200);
  CHECK(s.sources.fsu);
  CHECK(s.sources.fsu_after == 4000);
  CHECK(s.sources.rpb);
  CHECK(s.sources.split_min_votes == 20);
  CHECK(s.sources.wall_shift_sigma_cells == 2.0);
  CHECK(s.sources.door_min_width_m == 0.6);
  CHECK(s.sources.door_max_width_m == 2.0);
  REQUIRE(s.kernels.size() == 9);
  CHECK(s.kernels.front() == std::make_pair(std::string("ADD"), std::string("REMOVE")));
  CHECK(s.kernels.back() == std::make_pair(std::string("INTERCHANGE"), std::string("INTERCHANGE")));
  REQUIRE(s.schedule.size() == 3);
  CHECK(s.schedule[1].begin == 1000);
  CHECK(s.schedule[2].end == std::numeric_limits<std::uint64_t>::max());
}

namespace {
std::string error_of(const rd::DomainConfig& c) {
  try {
    (void)read_settings(c);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("calls the indoor kit does not implement are errors naming their line", "[indoor_kit]") {
  SECTION("unknown extractor") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.extract[4].call.name = "geom.window_count";
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:38") && Catch::Contains("geom.window_count"));
  }
  SECTION("unknown proposal source") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.kernels[0].sources[1].name = "detect.magic";
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:52") && Catch::Contains("detect.magic"));
  }
  SECTION("unknown prior") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.prior[1].call.name = "symmetry_penalty";
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:42"));
  }
  SECTION("unknown likelihood") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.likelihood[0].name = "grid.beam";
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:47"));
  }
  SECTION("a lut that is not 3x3") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.likelihood[0].args[0].value.items.pop_back();
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:47") && Catch::Contains("3x3"));
  }
  SECTION("a negative length") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.kernels[0].sources[0].args[0].value.number = -1.5;
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:51") && Catch::Contains("min_size"));
  }
  SECTION("an unknown kernel") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.kernels.push_back({"TELEPORT", "TELEPORT", {}, {}, "domains/indoor.ksm:62"});
    CHECK_THAT(error_of(c), Catch::Contains("domains/indoor.ksm:62") && Catch::Contains("TELEPORT"));
  }
  SECTION("a lenient type that is no unit type") {
    auto c = ksmc::tests::indoor_kit::indoor_config();
    c.likelihood[0].args[1].value.items.push_back(rd::Value::name("Kitchen"));
    CHECK_THAT(error_of(c), Catch::Contains("Kitchen"));
  }
}
