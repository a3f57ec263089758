// The development binary's path in-process: run_domain_main + kit on an example scene.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runtime/cli/domain_main.h"
#include "stdlib/tabletop/kit/domain_spec.h"
#include "tests/tabletop_kit/binding.h"
#include "tests/tabletop_kit/config_fixture.h"

namespace kit = ksmc::stdlib::tabletop::kit;
namespace fs = std::filesystem;
using namespace ksmc::tests::tabletop_kit;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

int run(const std::vector<std::string>& args, std::string& err) {
  std::vector<const char*> argv{"tabletop-dev"};
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, e;
  ksmc::runtime::cli::CliStreams io{out, e, false};
  const auto spec = kit::domain_spec(tabletop_config(recommended_tolerances()), tabletop_binding());
  const int rc = ksmc::runtime::cli::run_domain_main(static_cast<int>(argv.size()), argv.data(), spec, io);
  err = e.str();
  return rc;
}

}  // namespace

TEST_CASE("tabletop scene.json --out DIR writes the scene graph, deterministically") {
  const fs::path scene = fs::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json";
  const fs::path out1 = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_out1";
  const fs::path out2 = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_out2";
  fs::remove_all(out1);
  fs::remove_all(out2);
  std::string err;
  REQUIRE(run({scene.string(), "--out", out1.string(), "--seed", "5", "--iterations", "300", "-q"}, err) == 0);
  REQUIRE(run({scene.string(), "--out", out2.string(), "--seed", "5", "--iterations", "300", "-q"}, err) == 0);
  for (const char* f : {"scene_graph.json", "graph.dot", "overlay.png"}) {
    INFO(f);
    CHECK(fs::exists(out1 / f));
  }
  CHECK(slurp(out1 / "scene_graph.json") == slurp(out2 / "scene_graph.json"));
  const auto g = nlohmann::json::parse(slurp(out1 / "scene_graph.json"));
  REQUIRE(g.at("objects").size() == 7);
  for (const auto& o : g["objects"]) {
    for (const char* k : {"id", "pose", "stable", "false_prob", "hidden_prob", "false", "hidden"}) CHECK(o.contains(k));
    const double fp = o["false_prob"];
    CHECK((fp >= 0.0 && fp <= 1.0));
    if (fp > 0.6) CHECK(o["false"] == true);
    if (fp < 0.4) CHECK(o["false"] == false);
  }
  // The seed example: object 4 rests on 3, 0-3 on the table, 5 hovers, 6 intersects 1.
  const auto& sup = g.at("support");
  auto has = [&](const char* a, const char* b) {
    for (const auto& e : sup)
      if (e[0] == a && e[1] == b) return true;
    return false;
  };
  CHECK(has("4", "3"));
  CHECK(has("0", "table"));
  CHECK(has("3", "table"));
}

TEST_CASE("bad input exits 1 naming the file") {
  const fs::path bad = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/bad_scene.json";
  fs::create_directories(bad.parent_path());
  std::ofstream(bad) << "{\"camera\": 3}";
  std::string err;
  const fs::path out = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_bad";
  CHECK(run({bad.string(), "--out", out.string(), "-q"}, err) == 1);
  CHECK(err.find("bad_scene.json") != std::string::npos);
  CHECK(run({bad.string(), "--out", out.string(), "--input-format", "xml", "-q"}, err) == 2);
}
