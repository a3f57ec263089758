#include "tests/frontend/support.h"

#include <algorithm>
#include <sstream>

#include "compiler/build/loader.h"
#include "compiler/check/pass.h"
#include "compiler/diag/diagnostics.h"
#include "compiler/driver/pipeline.h"

namespace ksmc::tests::frontend {

namespace {

using namespace ksmc::compiler;

const std::string kPath = std::string(KSMC_SOURCE_DIR) + "/tests/frontend/snippet.ksm";

void collect(const diag::DiagEngine& diags, const diag::SourceManager& sources, Outcome& out) {
  for (const diag::Diagnostic& d : diags.all()) {
    std::string s;
    if (d.loc.file > 0) s += sources.path(d.loc.file) + ":";
    s += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + ": " + d.message;
    (d.severity == diag::Severity::Error ? out.errors : out.warnings).push_back(s);
  }
}

Outcome run(const std::string& text, const std::vector<std::string>& passes, bool checks, bool includes) {
  Outcome out;
  diag::SourceManager sources;
  diag::DiagEngine diags(sources);
  build::LoadOptions opts;
  opts.follow_includes = includes;
  out.loaded = build::load_program_text(kPath, text, opts, sources, diags, out.program);
  if (out.loaded && checks) {
    check::Context ctx{out.program, diags, {}};
    for (const auto& pass : driver::make_check_passes()) {
      const std::string name(pass->name());
      if (name == "symbols" || passes.empty() || std::find(passes.begin(), passes.end(), name) != passes.end()) {
        pass->run(ctx);
      }
    }
  }
  collect(diags, sources, out);
  std::ostringstream ss;
  diags.flush(ss);
  out.rendered = ss.str();
  return out;
}

}  // namespace

Outcome compile(const std::string& text, const std::vector<std::string>& passes) { return run(text, passes, true, true); }

Outcome parse_only(const std::string& text) { return run(text, {}, false, false); }

bool contains(const std::vector<std::string>& msgs, const std::string& needle) {
  return std::any_of(msgs.begin(), msgs.end(), [&](const std::string& m) { return m.find(needle) != std::string::npos; });
}

}  // namespace ksmc::tests::frontend
