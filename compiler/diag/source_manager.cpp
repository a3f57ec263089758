#include "compiler/diag/source_manager.h"

namespace ksmc::compiler::diag {

int SourceManager::add(std::string path, std::string text) {
  File f{std::move(path), std::move(text), {0}};
  for (std::size_t i = 0; i < f.text.size(); ++i) {
    if (f.text[i] == '\n') f.line_starts.push_back(i + 1);
  }
  files_.push_back(std::move(f));
  return static_cast<int>(files_.size() - 1);
}

std::string_view SourceManager::line(int id, int line) const {
  if (id < 0 || static_cast<std::size_t>(id) >= files_.size() || line < 1) return {};
  const File& f = files_[static_cast<std::size_t>(id)];
  const auto idx = static_cast<std::size_t>(line - 1);
  if (idx >= f.line_starts.size()) return {};
  const std::size_t begin = f.line_starts[idx];
  std::size_t end = idx + 1 < f.line_starts.size() ? f.line_starts[idx + 1] : f.text.size();
  while (end > begin && (f.text[end - 1] == '\n' || f.text[end - 1] == '\r')) --end;
  return std::string_view(f.text).substr(begin, end - begin);
}

}  // namespace ksmc::compiler::diag
