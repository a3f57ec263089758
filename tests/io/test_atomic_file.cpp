#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "runtime/io/atomic_file.h"

namespace fs = std::filesystem;
using ksmc::runtime::io::write_file_atomic;

TEST_CASE("write_file_atomic replaces content and leaves no temporary") {
  const fs::path dir = fs::temp_directory_path() / "ksmc_atomic_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path target = dir / "out.txt";
  write_file_atomic(target, std::string_view("first"));
  write_file_atomic(target, std::string_view("second"));
  std::ifstream in(target);
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str() == "second");
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 1);
  fs::remove_all(dir);
}

TEST_CASE("write_file_atomic names the path when the folder is missing") {
  const fs::path target = fs::temp_directory_path() / "ksmc_no_such_dir" / "x.json";
  try {
    write_file_atomic(target, std::string_view("x"));
    FAIL("expected an exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("ksmc_no_such_dir/x.json") != std::string::npos);
  }
}

TEST_CASE("rewrite_file_atomic writes through a symbolic link and keeps the mode") {
  const fs::path dir = fs::temp_directory_path() / "ksmc_rewrite_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "real.ksm") << "old";
  fs::permissions(dir / "real.ksm", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink("real.ksm", dir / "link.ksm");
  ksmc::runtime::io::rewrite_file_atomic(dir / "link.ksm", "new");
  CHECK(fs::is_symlink(dir / "link.ksm"));
  std::ifstream in(dir / "real.ksm");
  std::stringstream ss;
  ss << in.rdbuf();
  CHECK(ss.str() == "new");
  CHECK((fs::status(dir / "real.ksm").permissions() & fs::perms::all) ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  CHECK(files == 2);  // no temporary
  fs::remove_all(dir);
}
