#include "runtime/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace ksmc::runtime::io {

namespace {

std::runtime_error io_error(const std::filesystem::path& path, const char* what) {
  return std::runtime_error(path.string() + ": " + what + ": " + std::strerror(errno));
}

// mode < 0: the default mode of a new file.
void write_atomic(const std::filesystem::path& path, std::span<const unsigned char> data, int mode) {
  const std::filesystem::path tmp =
      path.string() + ".tmp." + std::to_string(static_cast<long>(::getpid()));
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f == nullptr) throw io_error(path, "cannot open for writing");
  if (mode >= 0) (void)::fchmod(::fileno(f), static_cast<mode_t>(mode));
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

std::span<const unsigned char> bytes_of(std::string_view data) {
  return {reinterpret_cast<const unsigned char*>(data.data()), data.size()};
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::span<const unsigned char> data) {
  write_atomic(path, data, -1);
}

void rewrite_file_atomic(const std::filesystem::path& path, std::string_view data) {
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::is_symlink(path, ec) ? std::filesystem::canonical(path, ec) : path;
  if (ec) throw std::runtime_error(path.string() + ": cannot follow the symbolic link: " + ec.message());
  struct stat st {};
  const int mode = ::stat(real.c_str(), &st) == 0 ? static_cast<int>(st.st_mode & 07777) : -1;
  write_atomic(real, bytes_of(data), mode);
}

void write_file_atomic(const std::filesystem::path& path, std::string_view data) {
  write_atomic(path, bytes_of(data), -1);
}

}  // namespace ksmc::runtime::io
