// libFuzzer target: parse + build + check of arbitrary bytes, then the fmt round-trip
// property (when the formatted text parses, it has the same AST). Built by scripts/fuzz.sh
// with clang -fsanitize=fuzzer,address; includes are not followed (no file access).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include "compiler/ast/dump.h"
#include "compiler/build/loader.h"
#include "compiler/driver/pipeline.h"
#include "compiler/fmt/formatter.h"
#include "compiler/fuzz/fuzz_files.h"
#include "compiler/parse/parser.h"

namespace {

using namespace ksmc::compiler;

struct Loaded {
  bool ok = false;
  std::string dump;
  std::string formatted;
};

Loaded load(const std::string& text) {
  Loaded out;
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions opts;
  opts.follow_includes = false;
  driver::FrontendResult r = driver::run_frontend("fuzz.ksm", opts, sources, diags, &text);
  std::ostringstream sink;  // rendering exercises the diagnostics printer
  diags.flush(sink);
  out.ok = r.loaded;
  if (r.loaded) {
    std::ostringstream d;
    ast::dump(r.program.modules.front(), d);
    out.dump = d.str();
    out.formatted = fmt::format_module(r.program.modules.front());
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // ANTLR's prediction caches grow with every new input path: bound them (docs/reliability.md).
  static const unsigned every = ksmc::fuzz::clear_caches_every();
  static unsigned runs = 0;
  if (every != 0 && ++runs % every == 0) ksmc::compiler::parse::clear_prediction_caches();
  const std::string text(reinterpret_cast<const char*>(data), size);
  const Loaded first = load(text);
  if (!first.ok) return 0;
  const Loaded again = load(first.formatted);
  if (again.ok && again.dump != first.dump) {
    std::cerr << "fmt changed the AST\n--- input\n" << text << "\n--- formatted\n" << first.formatted << "\n";
    std::abort();
  }
  if (again.ok && again.formatted != first.formatted) {
    std::cerr << "fmt is not idempotent\n--- once\n" << first.formatted << "\n--- twice\n" << again.formatted << "\n";
    std::abort();
  }
  return 0;
}
