// The ksmc-scenegen executable: writes the numbered files, is reproducible, rejects bad input.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {
int run(const std::string& args, const fs::path& log) {
  const std::string cmd = std::string("\"") + KSMC_SCENEGEN_EXE + "\" " + args + " > \"" + log.string() + "\" 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST_CASE("ksmc-scenegen writes reproducible numbered scenes", "[tabletop_sim][cli]") {
  const fs::path base = fs::path(KSMC_BINARY_DIR) / "test_output" / "tabletop_sim_cli";
  fs::remove_all(base);
  fs::create_directories(base);
  const std::string common = " --seed 7 --count 3 --objects 3..6 --hidden-rate 0.5 --false-rate 0.2";
  REQUIRE(run("--out \"" + (base / "a").string() + "\"" + common, base / "a.log") == 0);
  REQUIRE(run("--out \"" + (base / "b").string() + "\"" + common, base / "b.log") == 0);
  for (const char* f : {"scene_000.json", "scene_000.truth.json", "scene_001.json", "scene_001.truth.json",
                        "scene_002.json", "scene_002.truth.json"}) {
    INFO(f);
    REQUIRE(fs::exists(base / "a" / f));
    CHECK(slurp(base / "a" / f) == slurp(base / "b" / f));
  }
  CHECK(!fs::exists(base / "a" / "scene_003.json"));
  const std::string summary = slurp(base / "a.log");
  CHECK(summary.find("wrote 3 scenes") != std::string::npos);
}

TEST_CASE("ksmc-scenegen rejects bad arguments with a message", "[tabletop_sim][cli]") {
  const fs::path base = fs::path(KSMC_BINARY_DIR) / "test_output" / "tabletop_sim_cli_bad";
  fs::create_directories(base);
  const fs::path log = base / "log.txt";
  const std::string out = " --out \"" + (base / "x").string() + "\"";
  CHECK(run("--seed 1 --count 2 --objects 5..2" + out, log) == 2);
  CHECK(slurp(log).find("minimum 5 exceeds maximum 2") != std::string::npos);
  CHECK(run("--seed 1 --count 2 --hidden-rate 1.5" + out, log) == 2);
  CHECK(slurp(log).find("hidden-rate") != std::string::npos);
  CHECK(run("--seed x1 --count 2" + out, log) == 2);
  CHECK(slurp(log).find("--seed: 'x1' is not a valid number") != std::string::npos);
  CHECK(run("--seed 1 --count 2 --bogus 3" + out, log) == 2);
  CHECK(slurp(log).find("unknown option '--bogus'") != std::string::npos);
  CHECK(run("--seed 1" + out, log) == 2);
  CHECK(slurp(log).find("--count is required") != std::string::npos);
  CHECK(!fs::exists(base / "x" / "scene_000.json"));
}
