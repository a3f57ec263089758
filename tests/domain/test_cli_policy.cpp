// The common CLI's error policy and standard outputs for kits (runtime/cli): a
// runtime::domain::ConfigError anywhere in load / run / write is an internal error (exit 3,
// saying so, no abort); --evidence-out FILE writes DomainSetup::evidence_db atomically.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/cli/domain_main.h"
#include "runtime/domain/config_error.h"
#include "tests/mcmc/toy_domain.h"

namespace fs = std::filesystem;
namespace cli = ksmc::runtime::cli;
namespace dom = ksmc::runtime::domain;
namespace toy = ksmc::tests::mcmc;

namespace {

struct Run {
  int code;
  std::string err;
};

Run run(const cli::DomainSpec& spec, std::vector<std::string> args) {
  args.insert(args.begin(), "toy");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = cli::run_domain_main(static_cast<int>(argv.size()), argv.data(), spec, cli::CliStreams{out, err, false});
  return {code, err.str()};
}

struct Dir {
  fs::path path = fs::temp_directory_path() / "ksmc_domain_cli_policy";
  Dir() {
    fs::remove_all(path);
    fs::create_directories(path);
    std::ofstream(path / "in.json") << R"({"n": 20, "start": 3})";
  }
  ~Dir() { fs::remove_all(path); }
  std::string input() const { return (path / "in.json").string(); }
  std::string out() const { return (path / "out").string(); }
};

// The toy domain with an evidence hook: the best state as one atom.
cli::DomainSpec with_evidence() {
  cli::DomainSpec spec = toy::toy_domain_spec();
  spec.load = [base = spec.load](const cli::DomainInput& in) {
    cli::DomainSetup s = base(in);
    s.evidence_db = [](ksmc::runtime::mcmc::Model& best) {
      return "At(x" + std::to_string(static_cast<toy::ToyModel&>(best).x()) + ")\n";
    };
    return s;
  };
  return spec;
}

const char* const kInternal = "(ksmc check accepted this domain file; please report it)";

}  // namespace

TEST_CASE("cli policy: a ConfigError from load is an internal error, exit 3", "[domain][cli]") {
  const Dir d;
  cli::DomainSpec spec = toy::toy_domain_spec();
  spec.load = [](const cli::DomainInput&) -> cli::DomainSetup { throw dom::ConfigError("toy kit: no such move"); };
  const Run r = run(spec, {d.input(), "--out", d.out(), "--quiet"});
  CHECK(r.code == cli::kExitInternal);
  CHECK(r.code == 3);
  CHECK(r.err == std::string("toy: internal error: toy kit: no such move ") + kInternal + "\n");
}

TEST_CASE("cli policy: a ConfigError from a model during the run is an internal error, exit 3", "[domain][cli]") {
  const Dir d;
  cli::DomainSpec spec = toy::toy_domain_spec();
  spec.load = [base = spec.load](const cli::DomainInput& in) {
    cli::DomainSetup s = base(in);
    s.model_factory = [](unsigned) -> std::unique_ptr<ksmc::runtime::mcmc::Model> {
      throw dom::ConfigError("toy kit: label set");
    };
    return s;
  };
  const Run r = run(spec, {d.input(), "--out", d.out(), "--quiet", "--iterations", "10"});
  CHECK(r.code == 3);
  CHECK(r.err.rfind("toy: internal error: ", 0) == 0);
  CHECK(r.err.find("toy kit: label set") != std::string::npos);
  CHECK(r.err.find(kInternal) != std::string::npos);
}

TEST_CASE("cli policy: a ConfigError while writing results is an internal error, exit 3", "[domain][cli]") {
  const Dir d;
  cli::DomainSpec spec = with_evidence();
  spec.load = [base = spec.load](const cli::DomainInput& in) {
    cli::DomainSetup s = base(in);
    s.evidence_db = [](ksmc::runtime::mcmc::Model&) -> std::string { throw dom::ConfigError("toy kit: output"); };
    return s;
  };
  const Run r = run(spec, {d.input(), "--out", d.out(), "--quiet", "--iterations", "10", "--evidence-out",
                           (d.path / "e.db").string()});
  CHECK(r.code == 3);
  CHECK(r.err.find("internal error: toy kit: output") != std::string::npos);
  CHECK_FALSE(fs::exists(d.path / "e.db"));
}

TEST_CASE("cli outputs: --evidence-out writes the best state's evidence", "[domain][cli]") {
  const Dir d;
  const fs::path db = d.path / "best.db";
  const Run r = run(with_evidence(), {d.input(), "--out", d.out(), "--quiet", "--iterations", "300", "--seed", "4",
                                      "--evidence-out", db.string()});
  REQUIRE(r.code == 0);
  std::ifstream f(db);
  std::stringstream text;
  text << f.rdbuf();
  std::ifstream result(fs::path(d.out()) / "toy_result.json");
  const auto j = nlohmann::json::parse(result);
  CHECK(text.str() == "At(x" + std::to_string(j.at("x").get<int>()) + ")\n");
  // No temporary left next to it.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(d.path)) ++files;
  CHECK(files == 3);  // in.json, out/, best.db
}

TEST_CASE("cli outputs: --evidence-out for a domain without evidence is a usage error", "[domain][cli]") {
  const Dir d;
  const Run r = run(toy::toy_domain_spec(), {d.input(), "--out", d.out(), "--quiet", "--evidence-out",
                                            (d.path / "e.db").string()});
  CHECK(r.code == 2);
  CHECK(r.err.find("--evidence-out") != std::string::npos);
}
