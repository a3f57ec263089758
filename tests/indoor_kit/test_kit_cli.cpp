// indoor-dev end to end through its command line: bad input gives a clear message, a
// non-zero exit and no output folder; the simulated office map is explained against its truth.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "stdlib/indoor/io/world_json_read.h"
#include "tests/indoor_kit/kit_fixture.h"

namespace fs = std::filesystem;
using namespace ksmc::tests::indoor_kit;

namespace {

struct Outcome {
  int code = -1;
  std::string err;
};

Outcome run_dev(const std::string& args, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt";
  const std::string cmd = std::string(INDOOR_DEV) + " " + args + " --quiet 2> " + err.string() + " > /dev/null";
  const int st = std::system(cmd.c_str());
  Outcome o;
  o.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  std::ifstream f(err);
  std::stringstream ss;
  ss << f.rdbuf();
  o.err = ss.str();
  return o;
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream f(p, std::ios::binary);
  f << bytes;
}

}  // namespace

TEST_CASE("indoor-dev: bad input fails cleanly without an output folder", "[indoor_kit][cli]") {
  const fs::path d = temp_dir("cli_bad");
  write_bytes(d / "noimage.png", "this is not an image at all\n");
  write_bytes(d / "nores.yaml", "image: plan.pgm\norigin: [0, 0, 0]\n");
  write_bytes(d / "tiny.pgm", std::string("P5\n1 1\n255\n") + '\xfe');
  write_bytes(d / "huge.pgm", "P5\n20000 20000\n255\n");
  write_bytes(d / "dark.pgm", std::string("P5\n8 8\n255\n") + std::string(64, '\0'));
  const std::vector<std::pair<std::string, std::string>> cases{
      {"missing.png", "missing.png"}, {"noimage.png", "noimage.png"}, {"nores.yaml", "resolution"},
      {"tiny.pgm", "tiny.pgm"},       {"huge.pgm", "huge.pgm"},       {"dark.pgm", "free"}};
  for (const auto& [file, needle] : cases) {
    const fs::path out = d / ("out_" + file);
    const Outcome o = run_dev((d / file).string() + " --out " + out.string(), d);
    INFO(file << ": " << o.err);
    CHECK(o.code == 1);
    CHECK_THAT(o.err, Catch::Contains(needle));
    CHECK(!fs::exists(out));
  }
  const Outcome u = run_dev((d / "tiny.pgm").string() + " --robot 1 --out " + (d / "o").string(), d);
  CHECK(u.code != 0);
}

TEST_CASE("indoor-dev: the simulated office against its truth", "[indoor_kit][cli][slow]") {
  const fs::path src = fs::path(KSMC_SOURCE_DIR) / "examples/indoor";
  const fs::path d = temp_dir("cli_office");
  const fs::path out = d / "out";
  const Outcome o = run_dev((src / "sim_office.yaml").string() + " --out " + out.string() + " --seed 1 --iterations 20000", d);
  INFO(o.err);
  REQUIRE(o.code == 0);
  for (const char* f : {"world.json", "labels.png", "segmentation.png", "overlay.png", "graph.dot", "summary.json"})
    CHECK(fs::exists(out / f));
  CHECK(!fs::exists(out / "trace.png"));  // no --trace: nothing recorded, no picture
  const auto result = ksmc::stdlib::indoor::io::read_world_json(out / "world.json");
  const auto truth = ksmc::stdlib::indoor::io::read_world_json(src / "sim_office_truth.json");
  const double k = result.metrics.at("cell_prediction_rate");
  // Types are the domain's predicate names (Room, Corr, Hall); the truth file says room, corridor, hall.
  auto count = [](const ksmc::stdlib::indoor::io::WorldResult& w, const std::string& t) {
    int n = 0;
    for (const auto& u : w.units) n += u.type == t;
    return n;
  };
  std::cout << "sim_office: K " << k << ", units " << result.units.size() << " (truth " << truth.units.size()
            << "), rooms " << count(result, "Room") << " (truth " << count(truth, "room") << "), corridors "
            << count(result, "Corr") << " (truth " << count(truth, "corridor") << "), halls "
            << count(result, "Hall") << " (truth " << count(truth, "hall") << "), doors " << result.doors.size()
            << " (truth " << truth.doors.size() << ")\n";
  CHECK(k >= 0.85);
  CHECK(count(result, "Room") >= 3);
  // Every unit is typed by the domain's type group, and every query predicate is reported.
  const auto world = nlohmann::json::parse(std::ifstream(out / "world.json"));
  CHECK(world.at("types") == nlohmann::json::array({"Room", "Corr", "Hall", "Other"}));
  for (const char* q : {"Room", "Corr", "Hall", "Other", "SaLe"}) CHECK(world.at("queries").contains(q));
  for (const auto& u : world.at("units")) {
    double total = 0.0;
    for (const auto& [t, p] : u.at("type_probs").items()) total += p.get<double>();
    CHECK(total == Approx(1.0).epsilon(0.02));
    CHECK(world.at("queries").at(u.at("type").get<std::string>()).contains("u" + std::to_string(u.at("id").get<int>())));
  }
  std::ifstream dot(out / "graph.dot");
  const std::string dot_text((std::istreambuf_iterator<char>(dot)), std::istreambuf_iterator<char>());
  // Every typed node is labelled with its type's letter and its id (R12, C3, H7, O9).
  for (const auto& u : world.at("units")) {
    const std::string label = "label=\"" + u.at("type").get<std::string>().substr(0, 1) + std::to_string(u.at("id").get<int>()) + "\"";
    CHECK(dot_text.find(label) != std::string::npos);
  }
}

TEST_CASE("indoor-dev: --path, --samples and the map-reader outputs", "[indoor_kit][cli]") {
  const fs::path src = fs::path(KSMC_SOURCE_DIR) / "examples/indoor";
  const fs::path d = temp_dir("cli_path");
  const std::string map = (src / "sim_office.yaml").string() + " --seed 1 --iterations 3000";
  // Two points in the top-left room (metres, map frame): a route inside one unit.
  const Outcome o = run_dev(map + " --out " + (d / "a").string() + " --samples 20 --trace --path 4.25,14.5 5.5,12", d);
  INFO(o.err);
  REQUIRE(o.code == 0);
  for (const char* f : {"segmentation.png", "world.obj", "posterior.png", "path.json", "trace.png", "trace.csv"})
    CHECK(fs::exists(d / "a" / f));
  const auto path = nlohmann::json::parse(std::ifstream(d / "a" / "path.json"));
  CHECK(path.at("found") == true);
  CHECK(path.at("units").size() == 1);
  CHECK(path.at("waypoints_m").front() == nlohmann::json::array({4.25, 14.5}));
  const auto summary = nlohmann::json::parse(std::ifstream(d / "a" / "summary.json"));
  std::vector<std::string> listed;
  for (const auto& f : summary.at("outputs")) listed.push_back(f.at("path").get<std::string>());
  for (const char* f : {"segmentation.png", "world.obj", "posterior.png", "path.json"})
    CHECK(std::find(listed.begin(), listed.end(), f) != listed.end());
  // Without --samples there is no posterior.png (nothing to draw).
  const Outcome n = run_dev(map + " --out " + (d / "b").string() + " --path 29.2,17 4.25,14.5", d);
  CHECK(n.code == 0);
  CHECK(!fs::exists(d / "b" / "posterior.png"));
  // A start in no unit (the grey area right of the top rooms): the error is printed and in path.json.
  CHECK_THAT(n.err, Catch::Contains("--path: the start is outside every unit"));
  CHECK(nlohmann::json::parse(std::ifstream(d / "b" / "path.json")).at("found") == false);
  // A resolution conflict (the YAML's 0.05 against --resolution) is printed, not only stored.
  const Outcome r = run_dev((src / "sim_office.yaml").string() + " --iterations 200 --resolution 0.1 --out " + (d / "r").string(), d);
  CHECK(r.code == 0);
  CHECK_THAT(r.err, Catch::Contains("warning: resolution 0.05 from the YAML overridden by 0.1"));
  // Outside the map: a usage error before sampling.
  const Outcome u = run_dev(map + " --out " + (d / "c").string() + " --path 4.25,14.5 45,5", d);
  CHECK(u.code == 2);
  CHECK_THAT(u.err, Catch::Contains("--path 45,5: outside the map"));
  CHECK(!fs::exists(d / "c"));
}
