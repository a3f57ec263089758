// Whole-folder atomic outputs: the target holds the previous complete folder until
// commit(), then the new one; no stale file, no staging folder left behind.
#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "runtime/io/cancel.h"
#include "runtime/io/sha256.h"
#include "runtime/io/staged_dir.h"

namespace fs = std::filesystem;
using ksmc::runtime::io::StagedDir;

namespace {

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

struct Sandbox {
  fs::path root = fs::temp_directory_path() / "ksmc_staged_dir_test";
  Sandbox() {
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~Sandbox() { fs::remove_all(root); }
};

}  // namespace

TEST_CASE("staged dir: new folder appears whole at commit, nothing before") {
  Sandbox s;
  const fs::path out = s.root / "a" / "out";
  {
    StagedDir d(out);
    put(d.staging() / "x.txt", "xx");
    fs::create_directories(d.staging() / "sub");
    put(d.staging() / "sub" / "y.txt", "abc");
    CHECK_FALSE(fs::exists(out));
    const auto m = d.manifest();
    REQUIRE(m.size() == 2);
    CHECK(m[0].path == "sub/y.txt");
    CHECK(m[0].bytes == 3);
    CHECK(m[0].sha256 == ksmc::runtime::io::sha256_hex("abc"));
    CHECK(m[1].path == "x.txt");
    CHECK(d.manifest("x.txt").size() == 1);
    d.commit();
  }
  CHECK(names_in(out) == std::vector<std::string>{"sub", "x.txt"});
  CHECK(names_in(s.root / "a") == std::vector<std::string>{"out"});  // no staging left
}

TEST_CASE("staged dir: replaces an earlier output whole; stale files go; uncommitted leaves it intact") {
  Sandbox s;
  const fs::path out = s.root / "out";
  fs::create_directories(out);
  put(out / "summary.json", "{}");
  put(out / "trace.csv", "old");
  {
    StagedDir d(out);
    put(d.staging() / "summary.json", "{\"new\":1}");
    // destroyed without commit: an error or a kill before the rename
  }
  CHECK(names_in(out) == std::vector<std::string>{"summary.json", "trace.csv"});
  CHECK(slurp(out / "summary.json") == "{}");
  CHECK(names_in(s.root) == std::vector<std::string>{"out"});
  {
    StagedDir d(out);
    put(d.staging() / "summary.json", "{\"new\":1}");
    d.commit();
  }
  CHECK(names_in(out) == std::vector<std::string>{"summary.json"});  // trace.csv of the earlier run is gone
  CHECK(slurp(out / "summary.json") == "{\"new\":1}");
  CHECK(names_in(s.root) == std::vector<std::string>{"out"});
}

TEST_CASE("staged dir: refuses to replace a folder that is not a ksmc output, or a file") {
  Sandbox s;
  fs::create_directories(s.root / "home");
  put(s.root / "home" / "thesis.tex", "precious");
  CHECK_THROWS_WITH(StagedDir(s.root / "home"), Catch::Contains("home: the output folder exists, is not empty"));
  CHECK(slurp(s.root / "home" / "thesis.tex") == "precious");
  put(s.root / "file", "x");
  CHECK_THROWS_WITH(StagedDir(s.root / "file"), Catch::Contains("exists and is not a folder"));
  CHECK_THROWS_WITH(StagedDir(s.root / "file" / "sub"), Catch::Contains("file/sub: cannot create output folder"));
  CHECK(names_in(s.root) == std::vector<std::string>{"file", "home"});
}

TEST_CASE("staged dir: a link to an output folder is kept, its target replaced; abandoned staging removed") {
  Sandbox s;
  fs::create_directories(s.root / "real");
  put(s.root / "real" / "summary.json", "{}");
  fs::create_directory_symlink("real", s.root / "link");
  // What a process killed before its rename leaves (pid 2^22 + 1 is beyond pid_max's default).
  fs::create_directories(s.root / ".real.staging-4194305");
  {
    StagedDir d(s.root / "link");
    put(d.staging() / "summary.json", "new");
    d.commit();
  }
  CHECK(fs::is_symlink(s.root / "link"));
  CHECK(slurp(s.root / "link" / "summary.json") == "new");
  CHECK(names_in(s.root) == std::vector<std::string>{"link", "real"});
}

TEST_CASE("cancel: request keeps the first signal; names and exit codes") {
  using namespace ksmc::runtime::io;
  clear_cancel();
  CHECK_FALSE(cancel_requested());
  CHECK_NOTHROW(throw_if_cancelled("here"));
  request_cancel(15);
  request_cancel(2);
  CHECK(cancel_requested());
  CHECK(cancel_signal() == 15);
  CHECK(signal_name(cancel_signal()) == "SIGTERM");
  CHECK(interrupted_exit_code(15) == 143);
  CHECK(interrupted_exit_code(1) == 129);
  CHECK(interrupted_exit_code(0) == 130);
  CHECK_THROWS_AS(throw_if_cancelled("building"), Cancelled);
  CHECK_THROWS_WITH(throw_if_cancelled("building"), "building: interrupted by SIGTERM");
  clear_cancel();
}

TEST_CASE("cancel: the guard turns SIGTERM, SIGHUP and repeated SIGINT into a request, then restores") {
  using namespace ksmc::runtime::io;
  {
    SignalGuard g;
    std::raise(SIGINT);
    std::raise(SIGINT);  // no SA_RESETHAND: the second one does not kill
    std::raise(SIGTERM);
    std::raise(SIGHUP);
    CHECK(cancel_requested());
    CHECK(cancel_signal() == SIGINT);
  }
  {
    SignalGuard g;  // clears
    CHECK_FALSE(cancel_requested());
    std::raise(SIGHUP);
    CHECK(cancel_signal() == SIGHUP);
  }
  clear_cancel();
}
