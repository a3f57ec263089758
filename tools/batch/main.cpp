// ksmc-batch BIN INPUT... --out DIR [-j N] [-- ARGS...]
// Runs the domain binary BIN on every INPUT (OUT/<input stem>/, log OUT/<input stem>.log),
// N at a time (default: the number of cores), passing ARGS after each input, then writes
// OUT/batch.csv and OUT/batch.md (one row per input) and prints the Markdown table.
// Exit: 0 when every run succeeded, 1 when one failed, 2 on a usage error.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include "runtime/io/atomic_file.h"
#include "tools/batch/batch.h"

namespace fs = std::filesystem;
using namespace ksmc::tools::batch;

namespace {

int usage(const std::string& why) {
  std::cerr << "ksmc-batch: " << why << "\nusage: ksmc-batch BIN INPUT... --out DIR [-j N] [-- ARGS...]\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  Request r;
  r.jobs = std::max(1u, std::thread::hardware_concurrency());
  bool extra = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (extra) {
      r.extra.push_back(a);
    } else if (a == "--") {
      extra = true;
    } else if (a == "--out" || a == "-j") {
      if (i + 1 >= argc) return usage(a + " needs a value");
      const std::string v = argv[++i];
      if (a == "--out") {
        r.out = v;
      } else {
        char* end = nullptr;
        const long n = std::strtol(v.c_str(), &end, 10);
        if (*end != '\0' || n < 1 || n > 1024) return usage("-j must be a whole number in [1, 1024], got '" + v + "'");
        r.jobs = static_cast<unsigned>(n);
      }
    } else if (a == "--help" || a == "-h") {
      std::cout << "usage: ksmc-batch BIN INPUT... --out DIR [-j N] [-- ARGS...]\n";
      return 0;
    } else if (r.binary.empty()) {
      r.binary = a;
    } else {
      r.inputs.emplace_back(a);
    }
  }
  if (r.binary.empty()) return usage("no domain binary given");
  if (r.inputs.empty()) return usage("no input given");
  if (r.out.empty()) return usage("--out DIR is required");
  std::error_code ec;
  if (!fs::is_regular_file(r.binary, ec) || access(r.binary.c_str(), X_OK) != 0)
    return usage(r.binary.string() + ": not an executable file");
  r.binary = fs::absolute(r.binary);
  for (const auto& in : r.inputs)
    if (!fs::exists(in, ec)) return usage(in.string() + ": no such file");
  fs::create_directories(r.out, ec);
  if (ec) {
    std::cerr << "ksmc-batch: " << r.out.string() << ": cannot create the folder: " << ec.message() << "\n";
    return 1;
  }
  try {
    const auto rows = run_all(r);
    const Table t = make_table(rows);
    ksmc::runtime::io::write_file_atomic(r.out / "batch.csv", to_csv(t));
    const std::string md = to_markdown(t);
    ksmc::runtime::io::write_file_atomic(r.out / "batch.md", md);
    std::cout << md;
    int failed = 0;
    for (const auto& row : rows) failed += row.exit_code != 0;
    std::cerr << "ksmc-batch: " << rows.size() - static_cast<std::size_t>(failed) << " of " << rows.size()
              << " runs succeeded; table in " << (r.out / "batch.md").string() << " and batch.csv\n";
    return failed ? 1 : 0;
  } catch (const std::exception& e) {
    std::cerr << "ksmc-batch: " << e.what() << "\n";
    return 1;
  }
}
