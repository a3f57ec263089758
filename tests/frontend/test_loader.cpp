// Include resolution: search next to the file and in its parent folders, each file once
// (cycles are harmless), located errors for missing files and for errors inside includes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "compiler/build/loader.h"
#include "compiler/diag/diagnostics.h"
#include "compiler/driver/pipeline.h"

namespace fs = std::filesystem;
using namespace ksmc::compiler;

namespace {

fs::path scratch() {
  const fs::path dir = fs::path(KSMC_BINARY_DIR) / "tests-tmp" / "frontend_loader";
  fs::remove_all(dir);
  fs::create_directories(dir / "lib");
  fs::create_directories(dir / "proj" / "sub");
  return dir;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

struct Result {
  bool ok = false;
  std::size_t modules = 0;
  std::string stderr_text;
};

Result check_file(const fs::path& file, const std::vector<std::string>& dirs = {}) {
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions opts;
  opts.include_dirs = dirs;
  auto r = driver::run_frontend(file.string(), opts, sources, diags);
  std::ostringstream ss;
  diags.flush(ss);
  return Result{r.ok, r.program.modules.size(), ss.str()};
}

}  // namespace

TEST_CASE("includes are found in parent folders and -I dirs, each once", "[frontend][loader]") {
  const fs::path d = scratch();
  write(d / "proj" / "types.ksm", "include \"sub/preds.ksm\";\ntype t;\n");
  write(d / "proj" / "sub" / "preds.ksm", "include \"types.ksm\";\nevidence p(t);\n");  // cycle, found via the parent
  write(d / "proj" / "sub" / "main.ksm", "include \"types.ksm\";\ninclude \"types.ksm\";\ninclude \"extra.ksm\";\nhard p(x).\n");
  write(d / "lib" / "extra.ksm", "query q(t);\n");
  const Result r = check_file(d / "proj" / "sub" / "main.ksm", {(d / "lib").string()});
  INFO(r.stderr_text);
  CHECK(r.ok);
  CHECK(r.modules == 4);  // main, types, preds, extra
}

TEST_CASE("missing includes and errors inside includes are located", "[frontend][loader]") {
  const fs::path d = scratch();
  write(d / "proj" / "bad.ksm", "type t\n");
  write(d / "proj" / "main.ksm", "include \"nowhere.ksm\";\ninclude \"bad.ksm\";\n");
  const Result r = check_file(d / "proj" / "main.ksm");
  CHECK_FALSE(r.ok);
  CHECK(r.stderr_text.find("main.ksm:1:9: error: cannot find include file 'nowhere.ksm'") != std::string::npos);
  CHECK(r.stderr_text.find("bad.ksm:1:7: error: expected ';' after declaration, found end of file") != std::string::npos);
}
