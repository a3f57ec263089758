#include "ros/src/run_spec.h"

#include <sstream>

#include <unistd.h>

#include "runtime/cli/domain_main.h"

static_assert(ksmc::ros_nodes::kExitInterrupted == ksmc::runtime::cli::kExitInterrupted);

namespace ksmc::ros_nodes {

RunOutcome run_spec(const runtime::cli::DomainSpec& spec, const std::vector<std::string>& inputs,
                    const std::filesystem::path& out_dir, const RunSettings& s) {
  std::vector<std::string> args = {spec.name};
  args.insert(args.end(), inputs.begin(), inputs.end());
  for (const std::string& a : {std::string("--out"), out_dir.string(), std::string("--seed"), std::to_string(s.seed),
                               std::string("--iterations"), s.iterations == 0 ? std::string("auto") : std::to_string(s.iterations), std::string("--chains"),
                               std::to_string(s.chains), std::string("--quiet")})
    args.push_back(a);
  args.insert(args.end(), s.extra_args.begin(), s.extra_args.end());
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const runtime::cli::CliStreams streams{out, err, false};
  RunOutcome r;
  r.exit_code = runtime::cli::run_domain_main(static_cast<int>(argv.size()), argv.data(), spec, streams);
  r.messages = err.str();
  return r;
}

std::vector<std::string> split_args(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string a; in >> a;) out.push_back(a);
  return out;
}

std::filesystem::path fresh_folder(const std::string& prefix) {
  static unsigned counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(++counter));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace ksmc::ros_nodes
