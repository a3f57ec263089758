// Where an installed ksmc keeps its parts, found from the running executable:
//
//   P/bin/ksmc                       this program
//   P/share/ksmc/stdlib/*.ksm        the stdlib signatures (default include root)
//   P/lib/cmake/ksmc/ksmcConfig.cmake  the CMake package `ksmc build` compiles against
//
// (cmake/KsmcInstall.cmake writes this layout.) In a build tree none of these exist next to
// the executable, so nothing changes there.
#pragma once

#include <filesystem>
#include <optional>

namespace ksmc::compiler::driver {

// The running executable's absolute path (/proc/self/exe, else argv[0] made absolute).
std::filesystem::path self_executable(const char* argv0);

// P for an executable at P/bin/ksmc.
std::filesystem::path install_prefix_of(const std::filesystem::path& executable);

// P/share/ksmc when it holds a stdlib/ folder: the include root searched after -I dirs.
std::optional<std::filesystem::path> installed_stdlib_root(const std::filesystem::path& executable);

// P/lib/cmake/ksmc when it holds ksmcConfig.cmake.
std::optional<std::filesystem::path> installed_package_dir(const std::filesystem::path& executable);

}  // namespace ksmc::compiler::driver
