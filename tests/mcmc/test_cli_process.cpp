// End to end: the toy domain binary gets real signals from outside while sampling.
// SIGINT (also twice), SIGTERM and SIGHUP stop it; it writes complete outputs marked with
// the signal and exits 128 + signal. SIGKILL leaves the previous output folder intact.
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

namespace {

struct Sandbox {
  fs::path dir;
  explicit Sandbox(const std::string& name) : dir(fs::temp_directory_path() / ("ksmc_cli_process_" + name)) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir / "toy.json") << R"({"n": 20, "start": 2})";
  }
  ~Sandbox() { fs::remove_all(dir); }
};

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// Starts the toy binary on a practically endless run, waits until it samples, sends
// `signals` (10 ms apart) and returns its wait status (fails after 30 s).
int run_and_signal(const Sandbox& s, const fs::path& out, const std::vector<int>& signals) {
  const fs::path exe = fs::path(KSMC_BINARY_DIR) / "bin" / "ksmc_toy_domain";
  REQUIRE(fs::exists(exe));
  const fs::path ready = s.dir / "ready";
  fs::remove(ready);
  std::vector<std::string> args = {exe.string(), (s.dir / "toy.json").string(), "--iterations", "100000000000",
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
  const auto start = std::chrono::steady_clock::now();
  while (!fs::exists(ready) && std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  const bool started = fs::exists(ready);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (!started) ::kill(pid, SIGKILL);
  for (const int sig : signals) {
    if (started) ::kill(pid, sig);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  int status = 0;
  pid_t done = 0;
  for (int i = 0; i < 3000 && done == 0; ++i) {
    done = ::waitpid(pid, &status, WNOHANG);
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (done == 0) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    FAIL("the domain binary did not stop within 30 s of the signal");
  }
  REQUIRE(started);
  return status;
}

bool staging_left(const fs::path& out) {
  const auto names = names_in(out.parent_path());
  return std::any_of(names.begin(), names.end(), [](const std::string& n) { return n.rfind(".out.", 0) == 0; });
}

void check_complete(const fs::path& out, const std::string& signal) {
  CHECK(names_in(out) == std::vector<std::string>{"best_state.json", "report.html", "samples.jsonl", "summary.json",
                                                  "toy_result.json", "trace.csv"});
  const auto summary = nlohmann::json::parse(slurp(out / "summary.json"));
  CHECK(summary.at("cancelled") == true);
  CHECK(summary.at("interrupted") == signal);
  CHECK(summary.at("iterations").get<std::uint64_t>() > 0);
  CHECK(summary.at("chain_results").size() == 2);
  CHECK(summary.at("outputs").size() == 5);
}

}  // namespace

TEST_CASE("cli process: SIGINT, SIGINT twice, SIGTERM, SIGHUP -> complete outputs, exit 128 + signal") {
  struct Case {
    std::vector<int> signals;
    std::string name;
    int code;
  };
  for (const Case& c : {Case{{SIGINT}, "SIGINT", 130}, Case{{SIGINT, SIGINT, SIGINT}, "SIGINT", 130},
                        Case{{SIGTERM}, "SIGTERM", 143}, Case{{SIGHUP}, "SIGHUP", 129}}) {
    INFO(c.name << " x" << c.signals.size());
    Sandbox s("signals");
    const int status = run_and_signal(s, s.dir / "out", c.signals);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == c.code);
    check_complete(s.dir / "out", c.name);
    CHECK_FALSE(staging_left(s.dir / "out"));
  }
}

TEST_CASE("cli process: SIGKILL mid-run leaves the previous output folder intact") {
  Sandbox s("kill");
  const fs::path out = s.dir / "out";
  REQUIRE(WEXITSTATUS(run_and_signal(s, out, {SIGTERM})) == 143);
  const std::string before = slurp(out / "summary.json");
  const int status = run_and_signal(s, out, {SIGKILL});
  CHECK(WIFSIGNALED(status));
  CHECK(slurp(out / "summary.json") == before);
  check_complete(out, "SIGTERM");  // the earlier run's folder, untouched ...
  CHECK(staging_left(out));         // ... beside the killed run's hidden staging folder,
  REQUIRE(WEXITSTATUS(run_and_signal(s, out, {SIGHUP})) == 129);
  check_complete(out, "SIGHUP");
  CHECK_FALSE(staging_left(out));  // which the next run removed
}
