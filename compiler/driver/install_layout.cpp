#include "compiler/driver/install_layout.h"

#include <system_error>

namespace ksmc::compiler::driver {

namespace fs = std::filesystem;

fs::path self_executable(const char* argv0) {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && !self.empty()) return self;
  if (argv0 == nullptr) return {};
  self = fs::absolute(argv0, ec);
  return ec ? fs::path(argv0) : self.lexically_normal();
}

fs::path install_prefix_of(const fs::path& executable) {
  std::error_code ec;
  fs::path exe = fs::weakly_canonical(executable, ec);
  if (ec) exe = executable;
  return exe.parent_path().parent_path();
}

std::optional<fs::path> installed_stdlib_root(const fs::path& executable) {
  if (executable.empty()) return std::nullopt;
  const fs::path root = install_prefix_of(executable) / "share" / "ksmc";
  std::error_code ec;
  if (!fs::is_directory(root / "stdlib", ec)) return std::nullopt;
  return root;
}

std::optional<fs::path> installed_package_dir(const fs::path& executable) {
  if (executable.empty()) return std::nullopt;
  const fs::path dir = install_prefix_of(executable) / "lib" / "cmake" / "ksmc";
  std::error_code ec;
  if (!fs::is_regular_file(dir / "ksmcConfig.cmake", ec)) return std::nullopt;
  return dir;
}

}  // namespace ksmc::compiler::driver
