// Scratch files for the fuzz targets whose readers take a path (includes, scene.json,
// map YAML + image): a private folder per process (in /dev/shm when there is one), and a
// splitter for inputs holding several files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <unistd.h>

namespace ksmc::fuzz {

// Runs between clears of ANTLR's prediction caches in the .ksm targets (their growth is the
// front end's memory growth under fuzzing; docs/reliability.md). KSMC_FUZZ_CLEAR_EVERY
// overrides the default 1000; 0 = never.
inline unsigned clear_caches_every() {
  const char* v = std::getenv("KSMC_FUZZ_CLEAR_EVERY");
  return v == nullptr ? 1000U : static_cast<unsigned>(std::strtoul(v, nullptr, 10));
}

inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path base =
        std::filesystem::is_directory("/dev/shm") ? std::filesystem::path("/dev/shm") : std::filesystem::temp_directory_path();
    const auto d = base / ("ksmc-fuzz-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

// Empties the scratch folder and writes `files` (name -> bytes) into it.
inline void write_scratch(const std::vector<std::pair<std::string, std::string>>& files) {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(scratch_dir(), ec)) std::filesystem::remove_all(e.path(), ec);
  for (const auto& [name, bytes] : files) {
    const auto p = scratch_dir() / name;
    std::filesystem::create_directories(p.parent_path(), ec);
    std::ofstream(p, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
}

// A plain relative file name: [A-Za-z0-9_./-]{1,64}, no "..", not absolute.
inline bool safe_name(std::string_view n) {
  if (n.empty() || n.size() > 64 || n.front() == '/' || n.find("..") != std::string_view::npos) return false;
  for (const char c : n) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '.' || c == '/' || c == '-';
    if (!ok) return false;
  }
  return true;
}

// Splits "<first>\n<marker><name>\n<second>..." into files; the first is `first_name`.
// Sections with an unsafe name are dropped.
inline std::vector<std::pair<std::string, std::string>> split_files(std::string_view data, std::string_view marker,
                                                                    const std::string& first_name) {
  std::vector<std::pair<std::string, std::string>> out;
  std::string name = first_name;
  std::size_t pos = 0;
  for (;;) {
    const std::string needle = "\n" + std::string(marker);
    const std::size_t at = data.find(needle, pos);
    const std::string_view body = data.substr(pos, at == std::string_view::npos ? std::string_view::npos : at - pos);
    if (safe_name(name)) out.emplace_back(name, std::string(body));
    if (at == std::string_view::npos) break;
    const std::size_t name_start = at + needle.size();
    const std::size_t eol = data.find('\n', name_start);
    name = std::string(data.substr(name_start, eol == std::string_view::npos ? std::string_view::npos : eol - name_start));
    if (eol == std::string_view::npos) break;
    pos = eol + 1;
  }
  return out;
}

}  // namespace ksmc::fuzz
