#include "runtime/cli/domain_spec.h"

#include <charconv>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"

namespace ksmc::runtime::cli {

bool FlagValues::has(const std::string& name) const { return values_.count(name) != 0; }
bool FlagValues::given(const std::string& name) const { return given_.count(name) != 0; }

const std::string& FlagValues::text(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) throw UsageError(fmt::format("--{} is required", name));
  return it->second;
}

long long FlagValues::integer(const std::string& name) const {
  const std::string& s = text(name);
  long long v = 0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || s.empty()) {
    throw UsageError(fmt::format("--{}: expected an integer, got '{}'", name, s));
  }
  return v;
}

double FlagValues::real(const std::string& name) const {
  const std::string& s = text(name);
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size() || s.empty() || !std::isfinite(v)) {
    throw UsageError(fmt::format("--{}: expected a number, got '{}'", name, s));
  }
  return v;
}

bool FlagValues::toggle(const std::string& name) const {
  const auto it = values_.find(name);
  return it != values_.end() && it->second == "true";
}

void FlagValues::set(const std::string& name, std::string value, bool given) {
  values_[name] = std::move(value);
  if (given) given_.insert(name);
}

void FlagValues::set_words(const std::string& name, std::vector<std::string> words, bool given) {
  std::string joined;
  for (const auto& w : words) joined += (joined.empty() ? "" : " ") + w;
  set(name, std::move(joined), given);
  words_[name] = std::move(words);
}

std::vector<std::string> FlagValues::words(const std::string& name) const {
  const auto it = words_.find(name);
  if (it != words_.end()) return it->second;
  return {text(name)};
}

OutputDir::OutputDir(std::filesystem::path dir)
    : target_(std::move(dir)), staged_(std::make_shared<io::StagedDir>(target_)) {}

void OutputDir::write(const std::string& name, std::string_view data) {
  io::write_file_atomic(staged_->staging() / name, data);
  written_.push_back(name);
}

void OutputDir::write(const std::string& name, std::span<const unsigned char> data) {
  io::write_file_atomic(staged_->staging() / name, data);
  written_.push_back(name);
}

}  // namespace ksmc::runtime::cli
