#include "runtime/cli/file_hash.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace ksmc::runtime::cli {

std::string FileHash::hex() const { return fmt::format("{:016x}", fnv1a64); }

FileHash hash_file(const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) {
    throw std::runtime_error(fmt::format("{}: cannot open for reading: {}", path.string(), std::strerror(errno)));
  }
  FileHash h{path, 0, kFnvOffset};
  std::vector<char> buf(1 << 16);
  for (;;) {
    const std::size_t n = std::fread(buf.data(), 1, buf.size(), f.get());
    h.fnv1a64 = fnv1a64(std::string_view(buf.data(), n), h.fnv1a64);
    h.bytes += n;
    if (n < buf.size()) break;
  }
  if (std::ferror(f.get()) != 0) {
    throw std::runtime_error(fmt::format("{}: read error", path.string()));
  }
  return h;
}

}  // namespace ksmc::runtime::cli
