// End to end: the toy domain binary gets a real SIGINT from outside while sampling; it
// must stop, write complete outputs (no temporaries) and exit with 130.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

TEST_CASE("cli process: SIGINT from outside -> clean stop, complete outputs, exit 130") {
  const fs::path exe = fs::path(KSMC_BINARY_DIR) / "bin" / "ksmc_toy_domain";
  REQUIRE(fs::exists(exe));
  const fs::path dir = fs::temp_directory_path() / "ksmc_cli_process";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "toy.json") << R"({"n": 20, "start": 2})";
  const fs::path out = dir / "out";
  const fs::path ready = dir / "ready";

  std::vector<std::string> args = {exe.string(), (dir / "toy.json").string(), "--iterations", "100000000000",
                                   "--chains", "2", "--trace", "--samples", "5", "--burn-in", "0",
                                   "--out", out.string(), "--ready-file", ready.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int devnull = ::open("/dev/null", O_WRONLY);
    if (devnull >= 0) ::dup2(devnull, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  // Wait until sampling has started (the handler is installed by then), at most 60 s.
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(ready) && std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const bool started = fs::exists(ready);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ::kill(pid, started ? SIGINT : SIGKILL);
  int status = 0;
  // Give it time to stop and write; kill it if it hangs.
  pid_t done = 0;
  for (int i = 0; i < 3000 && done == 0; ++i) {
    done = ::waitpid(pid, &status, WNOHANG);
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (done == 0) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    FAIL("the domain binary did not stop within 30 s of SIGINT");
  }
  REQUIRE(started);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 130);

  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  CHECK(names == std::vector<std::string>{"best_state.json", "report.html", "samples.jsonl", "summary.json",
                                          "toy_result.json", "trace.csv"});
  std::ifstream f(out / "summary.json");
  const auto summary = nlohmann::json::parse(f);
  CHECK(summary.at("cancelled") == true);
  CHECK(summary.at("iterations").get<std::uint64_t>() > 0);
  CHECK(summary.at("chain_results").size() == 2);
  fs::remove_all(dir);
}
