#include "runtime/io/staged_dir.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include "runtime/io/sha256.h"

namespace ksmc::runtime::io {

namespace fs = std::filesystem;

namespace {

std::runtime_error folder_error(const fs::path& target, const std::string& what) {
  return std::runtime_error(target.string() + ": " + what);
}

// fsync a file or folder; errors are reported (a full disk can show up here).
void sync_path(const fs::path& p, bool directory) {
  const int fd = ::open(p.c_str(), (directory ? O_DIRECTORY : 0) | O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(p.string() + ": cannot open to flush: " + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int saved = errno;
  ::close(fd);
  if (rc != 0 && saved != EINVAL) {  // EINVAL: the file system cannot sync folders
    throw std::runtime_error(p.string() + ": cannot flush to disk: " + std::strerror(saved));
  }
}

// ".<name>.staging-<pid>" / ".<name>.old-<pid>" left by a process that no longer runs.
void remove_abandoned_siblings(const fs::path& parent, const std::string& name) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(parent, ec)) {
    const std::string f = e.path().filename().string();
    for (const std::string& prefix : {"." + name + ".staging-", "." + name + ".old-"}) {
      if (f.rfind(prefix, 0) != 0) continue;
      const std::string digits = f.substr(prefix.size());
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
      const long pid = std::strtol(digits.c_str(), nullptr, 10);
      if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
        std::error_code ignored;
        fs::remove_all(e.path(), ignored);
      }
    }
  }
}

}  // namespace

StagedDir::StagedDir(const fs::path& target, std::string_view marker_file) {
  std::error_code ec;
  fs::path t = fs::absolute(target, ec).lexically_normal();
  if (ec) throw folder_error(target, "cannot resolve the output folder: " + ec.message());
  if (!t.has_filename()) t = t.parent_path();  // "out/"
  if (fs::is_symlink(fs::symlink_status(t, ec))) {
    t = fs::canonical(t, ec);  // replace what the link points to, keep the link
    if (ec) throw folder_error(target, "output folder is a dangling symbolic link");
  }
  target_ = t;
  const fs::file_status st = fs::status(t, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) throw folder_error(target, "cannot create output folder: exists and is not a folder");
    const bool empty = fs::is_empty(t, ec);
    if (!empty && !fs::exists(t / marker_file, ec)) {
      throw folder_error(target, "the output folder exists, is not empty and holds no " + std::string(marker_file) +
                                     " (it is not an earlier output of ksmc); refusing to replace it: choose "
                                     "another --out or empty it");
    }
  }
  const fs::path parent = t.parent_path();
  fs::create_directories(parent, ec);
  if (ec || !fs::is_directory(parent)) {
    throw folder_error(target, "cannot create output folder: " + (ec ? ec.message() : std::string("not a directory")));
  }
  const std::string name = t.filename().string();
  remove_abandoned_siblings(parent, name);
  staging_ = parent / ("." + name + ".staging-" + std::to_string(static_cast<long>(::getpid())));
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec) || ec) {
    throw folder_error(target, "cannot create output folder (staging " + staging_.filename().string() +
                                   "): " + (ec ? ec.message() : std::string("exists")));
  }
}

StagedDir::~StagedDir() {
  if (committed_ || staging_.empty()) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

std::vector<StagedDir::Entry> StagedDir::manifest(std::string_view skip) const {
  std::vector<Entry> out;
  for (const auto& e : fs::recursive_directory_iterator(staging_)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = e.path().lexically_relative(staging_).generic_string();
    if (rel == skip) continue;
    const FileDigest d = sha256_file(e.path());
    out.push_back({rel, d.bytes, d.sha256});
  }
  std::sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.path < b.path; });
  return out;
}

void StagedDir::commit() {
  if (committed_) return;
  for (const auto& e : fs::recursive_directory_iterator(staging_)) {
    if (e.is_regular_file() || e.is_directory()) sync_path(e.path(), e.is_directory());
  }
  sync_path(staging_, true);
  std::error_code ec;
  const bool replace = fs::exists(target_, ec);
  if (replace) {
    // Atomic swap: the target is never missing, never mixed.
    if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0) {
      if (errno != EINVAL && errno != ENOSYS) {
        throw folder_error(target_, std::string("cannot move the new outputs into place: ") + std::strerror(errno));
      }
      // No exchange on this file system: move the old folder aside, then the new one in.
      const fs::path old = target_.parent_path() /
                           ("." + target_.filename().string() + ".old-" + std::to_string(static_cast<long>(::getpid())));
      fs::remove_all(old, ec);
      if (std::rename(target_.c_str(), old.c_str()) != 0) {
        throw folder_error(target_, std::string("cannot move the previous outputs aside: ") + std::strerror(errno));
      }
      if (std::rename(staging_.c_str(), target_.c_str()) != 0) {
        const int saved = errno;
        std::rename(old.c_str(), target_.c_str());
        throw folder_error(target_, std::string("cannot move the new outputs into place: ") + std::strerror(saved));
      }
      fs::remove_all(old, ec);
      committed_ = true;
    }
  } else if (std::rename(staging_.c_str(), target_.c_str()) != 0) {
    throw folder_error(target_, std::string("cannot move the new outputs into place: ") + std::strerror(errno));
  }
  if (!committed_) {
    committed_ = true;
    if (replace) fs::remove_all(staging_, ec);  // now holds the previous outputs
  }
  sync_path(target_.parent_path(), true);
}

}  // namespace ksmc::runtime::io
