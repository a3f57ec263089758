// (f) The common domain CLI on a toy domain: help, version, usage errors, input errors,
// atomic outputs, summary.json, reproducibility, Ctrl-C.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "runtime/cli/domain_main.h"
#include "runtime/cli/file_hash.h"
#include "runtime/cli/run_outputs.h"
#include "runtime/io/sha256.h"
#include "tests/mcmc/toy_domain.h"

namespace fs = std::filesystem;
namespace cli = ksmc::runtime::cli;
using ksmc::tests::mcmc::toy_domain_spec;

namespace {

struct Run {
  int code;
  std::string out;
  std::string err;
};

Run run(std::vector<std::string> args, bool tty = false) {
  args.insert(args.begin(), "toy");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out;
  std::ostringstream err;
  const int code = cli::run_domain_main(static_cast<int>(argv.size()), argv.data(), toy_domain_spec(),
                                        cli::CliStreams{out, err, tty});
  return {code, out.str(), err.str()};
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / ("ksmc_cli_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return path / name;
  }
};

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("cli: --help lists common and domain flags, exit 0") {
  const Run r = run({"--help"});
  CHECK(r.code == 0);
  for (const char* s : {"--seed", "--iterations", "--chains", "--out", "--samples", "--thin", "--trace",
                        "--quiet", "--version", "--start-override", "--interrupt-at", "two-bump"}) {
    INFO(s);
    CHECK(r.out.find(s) != std::string::npos);
  }
}

TEST_CASE("cli: --version names the domain and ksmc versions") {
  const Run r = run({"--version"});
  CHECK(r.code == 0);
  CHECK(r.out == "toy 1.2.3 (ksmc " + std::string(cli::ksmc_version()) + ")\n");
  CHECK(cli::ksmc_version() == KSMC_EXPECTED_VERSION);
}

TEST_CASE("cli: usage errors exit 2 with a message") {
  TempDir d("usage");
  const auto in = d.write("toy.json", R"({"n": 20, "start": 3})");
  const std::string out = (d.path / "out").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--bogus", in.string()}, "--bogus"},
      {{"--iterations", "many", in.string()}, "many"},
      {{"--chains", "0", in.string()}, "chains"},
      {{"--thin", "0", in.string()}, "thin"},
      {{"--iterations", "-5", in.string()}, "--iterations: expected a whole number from 1 to 18446744073709551615, got '-5' (negative)"},
      {{"--iterations=-5", in.string()}, "got '-5' (negative)"},
      {{"--iterations", "0", in.string()}, "--iterations: expected a whole number from 1"},
      {{"--seed", "-1", in.string()}, "--seed: expected a whole number from 0 to 18446744073709551615, got '-1'"},
      {{"--seed", "99999999999999999999999", in.string()}, "got '99999999999999999999999' (too large)"},
      {{"--burn-in", "-1", in.string()}, "--burn-in: expected a whole number from 0"},
      {{"--samples", "-3", in.string()}, "--samples: expected a whole number"},
      {{"--threads", "-1", in.string()}, "--threads: expected a whole number from 0 to 4096"},
      {{"--chains", "5000", in.string()}, "--chains: expected a whole number from 1 to 4096"},
      {{"--trace-every", "1e3", in.string()}, "--trace-every: expected a whole number"},
      {{"--max-input-mb", "0", in.string()}, "--max-input-mb: expected a whole number from 1"},
      {{}, "expected 1 toy.json, got 0"},
      {{in.string(), in.string()}, "expected 1 toy.json, got 2"},
      {{"--start-override", "x", in.string()}, "--start-override: expected an integer, got 'x'"},
      {{"--burn-in", "10", "--iterations", "5", in.string()}, "--burn-in 10 exceeds --iterations 5"},
      {{"--start-override", "99", in.string()}, "start must be in [0, n)"},
      {{"--iterations", "sometimes", in.string()}, "got 'sometimes', or auto (until the plateau)"},
      {{"--max-iterations", "500", in.string()}, "--max-iterations applies to --iterations auto only (here --iterations 5000)"},
      {{"--iterations", "100", "--plateau-window", "50", in.string()}, "--plateau-window applies to --iterations auto only"},
      {{"--iterations", "auto", "--plateau-gain", "nan", in.string()}, "--plateau-gain: expected a number >= 0, got 'nan'"},
      {{"--iterations", "auto", "--plateau-gain", "-1", in.string()}, "--plateau-gain: expected a number >= 0, got '-1'"},
      {{"--iterations", "auto", "--plateau-window", "0", in.string()}, "--plateau-window: expected a whole number from 1"},
      {{"--iterations", "auto", "--max-iterations", "0", in.string()}, "--max-iterations: expected a whole number from 1"},
  };
  for (const auto& c : cases) {
    auto args = c.args;
    args.insert(args.end(), {"--out", out, "--quiet"});
    const Run r = run(args);
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.err.find("--help") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(out));  // nothing written on a usage error
}

TEST_CASE("cli: bad input and unwritable output exit 1 naming the file") {
  TempDir d("errors");
  const auto bad = d.write("bad.json", R"({"n": 20,, })");
  Run r = run({bad.string(), "--out", (d.path / "o1").string(), "--quiet"});
  CHECK(r.code == 1);
  CHECK(r.err.find(bad.string() + ": invalid JSON") != std::string::npos);

  const auto small = d.write("small.json", R"({"n": 1})");
  r = run({small.string(), "--out", (d.path / "o2").string(), "--quiet"});
  CHECK(r.code == 1);
  CHECK(r.err.find("small.json: \"n\" must be at least 2") != std::string::npos);

  r = run({(d.path / "missing.json").string(), "--out", (d.path / "o3").string(), "--quiet"});
  CHECK(r.code == 1);
  CHECK(r.err.find("missing.json: cannot open") != std::string::npos);

  const auto good = d.write("toy.json", R"({"n": 20})");
  const auto blocker = d.write("file", "not a folder");
  r = run({good.string(), "--out", (blocker / "sub").string(), "--quiet", "--iterations", "10"});
  CHECK(r.code == 1);
  CHECK(r.err.find((blocker / "sub").string()) != std::string::npos);
  CHECK(files_in(d.path) == std::vector<std::string>{"bad.json", "file", "small.json", "toy.json"});

  // Inputs must be regular files under the size limit.
  r = run({d.path.string(), "--out", (d.path / "o4").string(), "--quiet"});
  CHECK(r.code == 1);
  CHECK(r.err.find(d.path.string() + ": expected a regular file, this is a folder") != std::string::npos);
  r = run({"/dev/zero", "--out", (d.path / "o5").string(), "--quiet"});
  CHECK(r.code == 1);
  CHECK(r.err.find("/dev/zero: expected a regular file, this is a character device") != std::string::npos);
  const auto big = d.write("big.json", R"({"n": 20})" + std::string(1500000, ' '));
  r = run({big.string(), "--out", (d.path / "o6").string(), "--quiet", "--max-input-mb", "1"});
  CHECK(r.code == 1);
  CHECK(r.err.find("big.json: 1.5 MB exceeds the input size limit of 1 MB (raise it with --max-input-mb)") !=
        std::string::npos);
  r = run({big.string(), "--out", (d.path / "o6").string(), "--quiet", "--max-input-mb", "2", "--iterations", "10"});
  CHECK(r.code == 0);

  // An existing folder that is not an earlier output is never replaced.
  fs::create_directories(d.path / "mine");
  d.write("mine/notes.txt", "keep");
  r = run({good.string(), "--out", (d.path / "mine").string(), "--quiet", "--iterations", "10"});
  CHECK(r.code == 1);
  CHECK(r.err.find("refusing to replace it") != std::string::npos);
  CHECK(files_in(d.path / "mine") == std::vector<std::string>{"notes.txt"});
}

TEST_CASE("cli: a full run writes complete outputs atomically and a correct summary") {
  TempDir d("run");
  const std::string input_text = R"({"n": 20, "start": 3})";
  const auto in = d.write("toy.json", input_text);
  const fs::path out = d.path / "out" / "nested";  // created if missing
  const Run r = run({in.string(), "--seed", "5", "--iterations", "20000", "--chains", "2", "--samples", "10",
                     "--thin", "100", "--trace", "--trace-every", "1000", "--out", out.string()});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(files_in(out) == std::vector<std::string>{"best_state.json", "report.html", "samples.jsonl", "summary.json",
                                                  "toy_result.json", "trace.csv"});  // no temporaries
  CHECK(r.err.find("it/s") != std::string::npos);  // plain progress lines when not a TTY
  CHECK(r.err.find('\r') == std::string::npos);

  const auto s = nlohmann::json::parse(slurp(out / "summary.json"));
  CHECK(s.at("ksmc_version") == std::string(cli::ksmc_version()));
  CHECK(s.at("domain").at("name") == "toy");
  CHECK(s.at("domain").at("version") == "1.2.3");
  CHECK(s.at("domain").at("n") == 20);
  CHECK(s.at("seed") == 5);
  CHECK(s.at("chains") == 2);
  CHECK(s.at("iterations") == 40000);
  CHECK(s.at("iterations_per_chain") == 20000);
  CHECK(s.at("burn_in") == 10000);
  CHECK(s.at("samples") == 20);
  CHECK(s.at("cancelled") == false);
  CHECK(s.at("seconds").get<double>() > 0.0);
  CHECK(s.at("iterations_per_second").get<double>() > 0.0);
  CHECK(s.at("hash_algorithm") == "fnv1a-64");
  REQUIRE(s.at("inputs").size() == 1);
  CHECK(s.at("inputs")[0].at("path") == in.string());
  CHECK(s.at("inputs")[0].at("bytes") == input_text.size());
  CHECK(s.at("inputs")[0].at("fnv1a64") == fmt::format("{:016x}", cli::fnv1a64(input_text)));
  CHECK(s.at("interrupted").is_null());
  // Every file of the folder but summary.json itself, sorted, with size and SHA-256.
  std::vector<std::string> listed;
  for (const auto& f : s.at("outputs")) {
    listed.push_back(f.at("path"));
    const std::string text = slurp(out / f.at("path").get<std::string>());
    CHECK(f.at("bytes") == text.size());
    CHECK(f.at("sha256") == ksmc::runtime::io::sha256_hex(text));
  }
  CHECK(listed == std::vector<std::string>{"best_state.json", "report.html", "samples.jsonl", "toy_result.json", "trace.csv"});
  std::uint64_t selected = 0;
  std::vector<std::string> names;
  for (const auto& k : s.at("kernels")) {
    names.push_back(k.at("name"));
    const auto sel = k.at("selected").get<std::uint64_t>();
    selected += sel;
    CHECK(k.at("proposed").get<std::uint64_t>() + k.at("declined").get<std::uint64_t>() == sel);
    CHECK(k.at("accepted").get<std::uint64_t>() + k.at("rejected").get<std::uint64_t>() == sel);
    CHECK(k.at("acceptance_rate").get<double>() ==
          Approx(sel == 0 ? 0.0 : k.at("accepted").get<double>() / static_cast<double>(sel)));
  }
  CHECK(names == std::vector<std::string>{"UP", "DOWN", "RESAMPLE"});
  CHECK(s.at("kernels")[0].at("reverse") == "DOWN");
  CHECK(selected == 40000);
  CHECK(s.at("chain_results").size() == 2);

  const auto best = nlohmann::json::parse(slurp(out / "best_state.json"));
  CHECK(best.at("state").at("x") == 4);  // the mode
  CHECK(best.at("log_posterior") == s.at("best").at("log_posterior"));
  CHECK(nlohmann::json::parse(slurp(out / "toy_result.json")).at("x") == 4);

  std::istringstream samples(slurp(out / "samples.jsonl"));
  int lines = 0;
  for (std::string line; std::getline(samples, line); ++lines) {
    const auto j = nlohmann::json::parse(line);
    CHECK(j.at("iteration").get<std::uint64_t>() > 10000);
    CHECK(j.at("state").contains("x"));
  }
  CHECK(lines == 20);
  const std::string trace = slurp(out / "trace.csv");
  CHECK(trace.rfind("chain,iteration,log_posterior,log_likelihood,log_prior,best_log_posterior,"
                    "acceptance_window,acceptance_total,acceptance_UP,acceptance_DOWN,acceptance_RESAMPLE\n",
                    0) == 0);
  CHECK(std::count(trace.begin(), trace.end(), '\n') == 1 + 2 * 20);

  // A second run into the same folder with other flags leaves no file of the first.
  const Run again = run({in.string(), "--iterations", "100", "--out", out.string(), "--quiet"});
  REQUIRE(again.code == 0);
  CHECK(files_in(out) == std::vector<std::string>{"best_state.json", "report.html", "summary.json", "toy_result.json"});
  CHECK(files_in(out.parent_path()) == std::vector<std::string>{"nested"});  // no staging folder left
}

TEST_CASE("cli: same seed, same outputs; TTY progress bar") {
  TempDir d("repro");
  const auto in = d.write("toy.json", R"({"n": 20, "start": 0})");
  auto args = [&](const std::string& o) {
    return std::vector<std::string>{in.string(), "--seed", "77", "--iterations", "30000", "--chains", "3",
                                    "--samples", "5", "--thin", "1000", "--trace", "--out", (d.path / o).string()};
  };
  const Run a = run(args("a"), true);
  auto quiet = args("b");
  quiet.push_back("--quiet");
  const Run b = run(quiet);
  REQUIRE(a.code == 0);
  REQUIRE(b.code == 0);
  CHECK(a.err.find('\r') != std::string::npos);  // the bar is redrawn in place
  CHECK(b.err.empty());                          // --quiet
  for (const char* f : {"best_state.json", "trace.csv", "samples.jsonl", "toy_result.json"}) {
    INFO(f);
    CHECK(slurp(d.path / "a" / f) == slurp(d.path / "b" / f));
  }
}

TEST_CASE("cli: Ctrl-C stops the run, writes complete outputs, exit 130") {
  TempDir d("interrupt");
  const auto in = d.write("toy.json", R"({"n": 20})");
  const fs::path out = d.path / "out";
  const Run r = run({in.string(), "--iterations", "100000000", "--interrupt-at", "2000", "--samples", "3",
                     "--burn-in", "0", "--trace", "--out", out.string(), "--quiet"});
  CHECK(r.code == 130);
  CHECK(r.err.find("interrupted by SIGINT") != std::string::npos);
  REQUIRE(fs::exists(out / "summary.json"));
  const auto s = nlohmann::json::parse(slurp(out / "summary.json"));
  CHECK(s.at("cancelled") == true);
  CHECK(s.at("interrupted") == "SIGINT");
  CHECK(s.at("iterations").get<std::uint64_t>() < 100000000);
  CHECK(files_in(out) == std::vector<std::string>{"best_state.json", "report.html", "samples.jsonl", "summary.json",
                                                  "toy_result.json", "trace.csv"});
}

TEST_CASE("cli: --iterations auto runs each chain until its plateau and says so") {
  TempDir d("auto");
  const auto in = d.write("toy.json", R"({"n": 20, "start": 3})");
  const fs::path out = d.path / "out";
  const std::vector<std::string> args{in.string(), "--seed", "3", "--iterations", "auto", "--plateau-window", "2000",
                                      "--chains", "2", "--samples", "4", "--thin", "10", "--out", out.string()};
  const Run r = run(args);
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("until the plateau, at most 2000000") != std::string::npos);  // progress: no percentage
  CHECK(r.err.find("warning") == std::string::npos);
  const auto s = nlohmann::json::parse(slurp(out / "summary.json"));
  CHECK(s.at("until_plateau").at("window") == 2000);
  CHECK(s.at("until_plateau").at("min_gain") == 0.0);
  CHECK(s.at("until_plateau").at("chains_reached") == 2);
  CHECK(s.at("iterations_per_chain") == 1000000);
  std::uint64_t total = 0;
  for (const auto& c : s.at("chain_results")) {
    const std::uint64_t it = c.at("iterations"), plateau = c.at("plateau_iteration");
    CHECK(it < 1000000);
    CHECK(it >= plateau + 2000);        // known one window after it began
    CHECK(c.at("best_iteration") <= plateau);  // nothing better came after
    CHECK(c.at("samples") == 4);
    total += it;
  }
  CHECK(s.at("iterations") == total);
  // The last samples of each chain (burn-in 0 with auto), oldest first, ending at the last iteration.
  std::istringstream lines(slurp(out / "samples.jsonl"));
  std::vector<nlohmann::json> samples;
  for (std::string line; std::getline(lines, line);) samples.push_back(nlohmann::json::parse(line));
  REQUIRE(samples.size() == 8);
  const std::uint64_t last0 = s.at("chain_results")[0].at("iterations");
  CHECK(samples[3].at("iteration") == last0);
  CHECK(samples[0].at("iteration") == last0 - 30);

  // Same seed, same stop (field by field: the seconds differ); a gain so large that every
  // window counts as flat stops one window after the first judgement.
  const Run again = run([&] { auto a = args; a.back() = (d.path / "again").string(); return a; }());
  REQUIRE(again.code == 0);
  const auto s2 = nlohmann::json::parse(slurp(d.path / "again" / "summary.json"));
  for (std::size_t c = 0; c < 2; ++c) {
    for (const char* k : {"iterations", "plateau_iteration", "best_iteration", "best_log_posterior"}) {
      INFO(k);
      CHECK(s2.at("chain_results")[c].at(k) == s.at("chain_results")[c].at(k));
    }
  }
  const Run loose = run({in.string(), "--iterations", "auto", "--plateau-window", "500", "--plateau-gain", "1e9",
                         "--out", (d.path / "loose").string(), "--quiet"});
  REQUIRE(loose.code == 0);
  const auto s3 = nlohmann::json::parse(slurp(d.path / "loose" / "summary.json"));
  CHECK(s3.at("chain_results")[0].at("iterations") == 600);  // judged every 100: 100 + 500
  CHECK(s3.at("until_plateau").at("min_gain_is") == "given (--plateau-gain)");
}

TEST_CASE("cli: --iterations auto warns when a chain reaches no plateau within --max-iterations") {
  TempDir d("auto_cap");
  const auto in = d.write("toy.json", R"({"n": 20, "start": 3})");
  const Run r = run({in.string(), "--iterations", "auto", "--plateau-window", "5000", "--max-iterations", "3000",
                     "--out", (d.path / "out").string(), "--quiet"});
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK(r.err.find("toy: warning: chain 0 reached no plateau within 3000 iterations") != std::string::npos);
  const auto s = nlohmann::json::parse(slurp(d.path / "out" / "summary.json"));
  CHECK(s.at("until_plateau").at("chains_reached") == 0);
  CHECK(s.at("chain_results")[0].at("plateau_iteration").is_null());
  CHECK(s.at("iterations") == 3000);
}
