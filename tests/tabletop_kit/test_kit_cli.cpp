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
#include "tests/tabletop_kit/binding_fixture.h"

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

int run(const std::vector<std::string>& args, std::string& err, const blk::Binding& binding = ksm_binding()) {
  std::vector<const char*> argv{"tabletop-dev"};
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, e;
  ksmc::runtime::cli::CliStreams io{out, e, false};
  const auto spec = kit::domain_spec(binding);
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
  // Every query atom's marginal, constants named by id; the decisions output's predicates
  // are among them with the reported values.
  const auto& q = g.at("queries");
  for (const char* pred : {"supported", "supportive", "hidden", "falseEst"}) {
    INFO(pred);
    REQUIRE(q.contains(pred));
    CHECK(q[pred].size() == 8);  // the table and 7 objects
    CHECK(q[pred].contains("table"));
  }
  for (const auto& o : g["objects"])
    CHECK(q["falseEst"][o["id"].get<std::string>()].get<double>() == Approx(o["false_prob"].get<double>()).margin(1e-6));
  CHECK(q["supported"]["4"].get<double>() > 0.9);  // 4 rests on 3
}

TEST_CASE("numeric object ids are accepted and echoed back as numbers") {
  const fs::path src = fs::path(KSMC_SOURCE_DIR) / "examples/tabletop/stack.json";
  auto doc = nlohmann::json::parse(slurp(src));
  std::vector<std::string> old_ids;
  for (std::size_t i = 0; i < doc["objects"].size(); ++i) {
    old_ids.push_back(doc["objects"][i]["id"].get<std::string>());
    doc["objects"][i]["id"] = 10 + static_cast<int>(i);
  }
  const fs::path scene = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/numeric_ids.json";
  fs::create_directories(scene.parent_path());
  std::ofstream(scene) << doc.dump(2);
  const fs::path out = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_numeric";
  fs::remove_all(out);
  std::string err;
  REQUIRE(run({scene.string(), "--out", out.string(), "--seed", "1", "--iterations", "50", "-q"}, err) == 0);
  const auto g = nlohmann::json::parse(slurp(out / "scene_graph.json"));
  REQUIRE(g["objects"].size() == doc["objects"].size());
  for (std::size_t i = 0; i < g["objects"].size(); ++i) {
    CHECK(g["objects"][i]["id"].is_number_integer());
    CHECK(g["objects"][i]["id"] == 10 + static_cast<int>(i));
  }
  REQUIRE_FALSE(g["support"].empty());
  for (const auto& e : g["support"]) {
    CHECK(e[0].is_number_integer());
    CHECK((e[1].is_number_integer() || e[1] == "table"));
  }
  CHECK(g["queries"]["hidden"].contains("10"));
  // --evidence-out names the constants as the queries do.
  const fs::path db = out / "evidence.db";
  REQUIRE(run({scene.string(), "--out", (out / "again").string(), "--seed", "1", "--iterations", "10", "-q",
               "--evidence-out", db.string()}, err) == 0);
  const std::string text = slurp(db);
  CHECK(text.find("(10)") != std::string::npos);
  CHECK(text.find("table") != std::string::npos);
}

TEST_CASE("--evidence-out refuses an id that is no .db constant, naming it") {
  const fs::path src = fs::path(KSMC_SOURCE_DIR) / "examples/tabletop/stack.json";
  auto doc = nlohmann::json::parse(slurp(src));
  doc["objects"][0]["id"] = "box one";
  const fs::path scene = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/spaced_id.json";
  std::ofstream(scene) << doc.dump(2);
  const fs::path out = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_spaced";
  fs::remove_all(out);
  std::string err;
  CHECK(run({scene.string(), "--out", out.string(), "--iterations", "5", "-q", "--evidence-out",
             (out / "e.db").string()}, err) == 1);
  CHECK(err.find("box one") != std::string::npos);
}

TEST_CASE("a domain without a decisions output reports relations and queries only") {
  const fs::path scene = fs::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json";
  const fs::path out = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_no_decisions";
  fs::remove_all(out);
  std::string err;
  REQUIRE(run({scene.string(), "--out", out.string(), "--seed", "2", "--iterations", "50", "-q"}, err,
              no_decisions_binding()) == 0);
  const auto g = nlohmann::json::parse(slurp(out / "scene_graph.json"));
  for (const auto& o : g["objects"]) {
    CHECK_FALSE(o.contains("false_prob"));
    CHECK_FALSE(o.contains("hidden"));
    CHECK(o.contains("stable"));
  }
  CHECK(g["queries"].contains("falseEst"));
  CHECK(fs::exists(out / "graph.dot"));
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

TEST_CASE("a binding the kit cannot run is an internal error (exit 3), never an abort") {
  static const blk::Binding broken = [] {
    blk::Binding b = ksm_binding();
    b.outputs[0].hidden = gen::kPred_higher;  // not a unary query
    return b;
  }();
  const fs::path scene = fs::path(KSMC_SOURCE_DIR) / "examples/tabletop/stack.json";
  const fs::path out = fs::path(KSMC_BINARY_DIR) / "tests/tabletop_kit/cli_broken";
  std::string err;
  CHECK(run({scene.string(), "--out", out.string(), "-q"}, err, broken) == 3);
  CHECK(err.find("internal error") != std::string::npos);
  CHECK(err.find("higher") != std::string::npos);
}

