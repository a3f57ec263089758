#include "runtime/io/dot_render.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "runtime/io/atomic_file.h"

extern char** environ;

namespace ksmc::runtime::io {

namespace {

std::filesystem::path find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    if (dir.empty()) continue;
    const auto candidate = std::filesystem::path(dir) / name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return {};
}

}  // namespace

std::string render_dot_png(const std::filesystem::path& dot_file, const std::filesystem::path& png_file,
                           const std::string& dot_executable) {
  const std::filesystem::path exe = dot_executable.empty() ? find_on_path("dot") : std::filesystem::path(dot_executable);
  if (exe.empty() || ::access(exe.c_str(), X_OK) != 0)
    return "Graphviz 'dot' not found" + (dot_executable.empty() ? std::string(" on PATH") : " at " + dot_executable) +
           "; skipping " + png_file.filename().string();
  const std::filesystem::path tmp = png_file.string() + ".dot-render.tmp";
  std::vector<std::string> args = {exe.string(), "-Tpng", dot_file.string(), "-o", tmp.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, exe.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    return "cannot start " + exe.string() + "; skipping " + png_file.filename().string();
  int status = 0;
  if (waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    return exe.string() + " -Tpng failed on " + dot_file.string() + "; skipping " + png_file.filename().string();
  }
  std::ifstream in(tmp, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  std::error_code ec;
  std::filesystem::remove(tmp, ec);
  write_file_atomic(png_file, bytes);
  return {};
}

}  // namespace ksmc::runtime::io
