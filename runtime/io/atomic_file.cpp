#include "runtime/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace ksmc::runtime::io {

namespace {

std::runtime_error io_error(const std::filesystem::path& path, const char* what) {
  return std::runtime_error(path.string() + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::span<const unsigned char> data) {
  const std::filesystem::path tmp =
      path.string() + ".tmp." + std::to_string(static_cast<long>(::getpid()));
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) throw io_error(path, "cannot open for writing");
  const bool wrote = data.empty() || std::fwrite(data.data(), 1, data.size(), f) == data.size();
  const bool flushed = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  const bool closed = std::fclose(f) == 0;
  if (!wrote || !flushed || !closed) {
    const int saved = errno;
    std::remove(tmp.c_str());
    errno = saved;
    throw io_error(path, "write failed");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    std::remove(tmp.c_str());
    errno = saved;
    throw io_error(path, "cannot rename temporary file into place");
  }
}

void write_file_atomic(const std::filesystem::path& path, std::string_view data) {
  write_file_atomic(path, std::span<const unsigned char>(
                              reinterpret_cast<const unsigned char*>(data.data()), data.size()));
}

}  // namespace ksmc::runtime::io
