#include "compiler/diag/diagnostics.h"

#include "compiler/diag/utf8.h"

#include <algorithm>
#include <climits>
#include <tuple>
#include <vector>

namespace ksmc::compiler::diag {

namespace {

bool is_continuation(unsigned char c) { return (c & 0xC0U) == 0x80U; }

// The caret line: one space (or tab) per code point before column `col`.
std::string caret_line(std::string_view line, int col) {
  std::string out;
  int cp = 1;
  for (std::size_t i = 0; i < line.size() && cp < col; ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (is_continuation(c)) continue;
    out += (c == '\t') ? '\t' : ' ';
    ++cp;
  }
  for (; cp < col; ++cp) out += ' ';
  out += '^';
  return out;
}

// Long lines are shown as a window of kWindow code points around the column, with "..."
// where text was cut; `col` is moved accordingly.
constexpr std::size_t kMaxShown = 160;
constexpr std::size_t kWindow = 120;

void clip_line(std::string& line, int& col) {
  std::vector<std::size_t> starts;  // byte offset of each code point
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (!is_continuation(static_cast<unsigned char>(line[i]))) starts.push_back(i);
  }
  const std::size_t n = starts.size();
  if (n <= kMaxShown) return;
  const std::size_t c = std::min(static_cast<std::size_t>(std::max(col, 1) - 1), n);
  const std::size_t begin = c > kWindow / 2 ? std::min(c - kWindow / 2, n - kWindow) : 0;
  const std::size_t end = begin + kWindow;
  const std::size_t b0 = starts[begin];
  const std::size_t b1 = end < n ? starts[end] : line.size();
  const std::string prefix = begin > 0 ? "..." : "";
  line = prefix + line.substr(b0, b1 - b0) + (end < n ? "..." : "");
  col = static_cast<int>(prefix.size() + (c - begin) + 1);
}

}  // namespace

std::string printable_line(std::string_view line) {
  std::string out;
  out.reserve(line.size());
  for (std::size_t i = 0; i < line.size();) {
    const std::size_t n = utf8_sequence_length(line, i);
    if (n == 0) {
      out += '?';
      ++i;
      continue;
    }
    const auto c = static_cast<unsigned char>(line[i]);
    if (n == 1 && ((c < 0x20 && c != '\t') || c == 0x7F)) {
      out += '?';
    } else {
      out.append(line.substr(i, n));
    }
    i += n;
  }
  return out;
}

void DiagEngine::add(Severity s, const ast::Loc& loc, std::string message) {
  diags_.push_back(Diagnostic{s, loc, std::move(message)});
  if (s == Severity::Error) {
    ++errors_;
  } else {
    ++warnings_;
  }
}

void DiagEngine::error(const ast::Loc& loc, std::string message) { add(Severity::Error, loc, std::move(message)); }
void DiagEngine::warning(const ast::Loc& loc, std::string message) { add(Severity::Warning, loc, std::move(message)); }

int DiagEngine::errors_in(int file) const {
  return static_cast<int>(std::count_if(diags_.begin(), diags_.end(), [&](const Diagnostic& d) {
    return d.severity == Severity::Error && d.loc.file == file;
  }));
}

void DiagEngine::flush(std::ostream& out) {
  // Line 0 marks a file-level diagnostic, printed after the file's located ones.
  auto key = [](const Diagnostic& d) {
    return std::make_tuple(d.loc.file, d.loc.line == 0 ? INT_MAX : d.loc.line, d.loc.col, d.severity == Severity::Warning,
                           d.message);
  };
  std::stable_sort(diags_.begin(), diags_.end(), [&](const Diagnostic& a, const Diagnostic& b) { return key(a) < key(b); });
  diags_.erase(std::unique(diags_.begin(), diags_.end(),
                           [&](const Diagnostic& a, const Diagnostic& b) { return key(a) == key(b); }),
               diags_.end());
  for (const Diagnostic& d : diags_) {
    const char* sev = d.severity == Severity::Error ? "error" : "warning";
    if (d.loc.file < 0 || static_cast<std::size_t>(d.loc.file) >= sources_.size()) {
      out << "ksmc: " << sev << ": " << d.message << '\n';
      continue;
    }
    if (d.loc.line == 0) {
      out << sources_.path(d.loc.file) << ": " << sev << ": " << d.message << '\n';
      continue;
    }
    out << sources_.path(d.loc.file) << ':' << d.loc.line << ':' << d.loc.col << ": " << sev << ": " << d.message
        << '\n';
    std::string line = printable_line(sources_.line(d.loc.file, d.loc.line));
    int col = d.loc.col;
    clip_line(line, col);
    out << line << '\n' << caret_line(line, col) << '\n';
  }
  diags_.clear();
}

}  // namespace ksmc::compiler::diag
