#include "runtime/mln/evidence.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "runtime/mln/error.h"

namespace ksmc::runtime::mln {

Evidence::Evidence(const Program& program, const Domain& domain) {
  values_.resize(program.predicates.size());
  radix_.resize(program.predicates.size());
  for (std::size_t p = 0; p < program.predicates.size(); ++p) {
    std::int64_t n = 1;
    for (auto t : program.predicates[p].arg_types) {
      const std::int32_t k = static_cast<std::size_t>(t) < domain.num_types() ? domain.size(t) : 0;
      radix_[p].push_back(k);
      n *= k;
    }
    values_[p].assign(static_cast<std::size_t>(n), kUnknown);
  }
}

std::int64_t Evidence::flat_index(std::int32_t predicate, std::span<const std::int32_t> args) const {
  const auto& r = radix_[predicate];
  std::int64_t idx = 0;
  for (std::size_t i = 0; i < r.size(); ++i) idx = idx * r[i] + args[i];
  return idx;
}

void Evidence::clear() {
  for (auto& v : values_) std::fill(v.begin(), v.end(), kUnknown);
}

namespace {

std::string_view trim(std::string_view s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

bool is_ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.' || c == '"';
}

bool valid_name(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!is_ident_char(c)) return false;
  return true;
}

}  // namespace

namespace {

struct ParsedAtom {
  bool value = true;
  std::string name;
  std::vector<std::string> args;
  std::string original;
};

// Parses one line; returns false for blank/comment lines. Throws on syntax errors.
bool parse_line(std::string_view line, const std::string& where, ParsedAtom& out) {
  if (const auto c = line.find("//"); c != std::string_view::npos) line = line.substr(0, c);
  line = trim(line);
  if (line.empty()) return false;
  out.original = std::string(line);
  out.value = true;
  out.args.clear();
  if (line.front() == '!') {
    out.value = false;
    line = trim(line.substr(1));
  }
  const auto open = line.find('(');
  if (open == std::string_view::npos || line.back() != ')') {
    throw MlnError(where + "malformed ground atom '" + out.original + "': expected name(arg, ...) or !name(arg, ...)");
  }
  out.name = std::string(trim(line.substr(0, open)));
  if (!valid_name(out.name)) throw MlnError(where + "malformed ground atom '" + out.original + "': bad predicate name");
  const std::string_view inner = line.substr(open + 1, line.size() - open - 2);
  if (!trim(inner).empty()) {
    std::size_t s = 0;
    while (true) {
      const auto comma = inner.find(',', s);
      out.args.emplace_back(trim(inner.substr(s, comma == std::string_view::npos ? std::string_view::npos : comma - s)));
      if (comma == std::string_view::npos) break;
      s = comma + 1;
    }
  }
  for (const auto& n : out.args) {
    if (!valid_name(n)) throw MlnError(where + "malformed ground atom '" + out.original + "': bad argument '" + n + "'");
  }
  return true;
}

}  // namespace

void check_db_text(std::string_view text, const std::string& filename) {
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n');
    throw MlnError(filename + ":" + std::to_string(line) + ": NUL byte at offset " + std::to_string(nul) +
                   " (a binary file, or UTF-16? evidence must be UTF-8 text)");
  }
}

namespace {

// Calls fn(where, atom, predicate) for every atom line, after the checks every pass shares.
template <typename Fn>
void for_each_atom(std::string_view text, const std::string& filename, const Program& program, Fn&& fn) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
  check_db_text(text, filename);
  std::int32_t line_no = 0;
  std::size_t pos = 0;
  ParsedAtom atom;
  while (pos <= text.size()) {
    // Lines end with \n, \r\n or a lone \r (old Mac files).
    const auto nl = text.find_first_of("\r\n", pos);
    const std::string_view line =
        text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos                                       ? text.size() + 1
          : text[nl] == '\r' && nl + 1 < text.size() && text[nl + 1] == '\n' ? nl + 2
                                                                              : nl + 1;
    ++line_no;
    const auto where = filename + ":" + std::to_string(line_no) + ": ";
    if (!parse_line(line, where, atom)) continue;
    const auto pred = program.find_predicate(atom.name);
    if (!pred) throw MlnError(where + "unknown predicate '" + atom.name + "'");
    const auto& p = program.predicates[*pred];
    if (atom.args.size() != p.arg_types.size()) {
      throw MlnError(where + "'" + atom.name + "' takes " + std::to_string(p.arg_types.size()) + " argument" +
                     (p.arg_types.size() == 1 ? "" : "s") + ", got " + std::to_string(atom.args.size()));
    }
    fn(where, line_no, atom, *pred);
  }
}

}  // namespace

void collect_db_constants(std::string_view text, const std::string& filename, const Program& program,
                          Domain& domain) {
  if (domain.num_types() < program.types.size()) domain.resize(program.types.size());
  for_each_atom(text, filename, program,
                [&](const std::string&, std::int32_t, const ParsedAtom& atom, std::int32_t pred) {
                  const auto& p = program.predicates[pred];
                  for (std::size_t i = 0; i < atom.args.size(); ++i) domain.add(p.arg_types[i], atom.args[i]);
                });
}

void parse_db(std::string_view text, const std::string& filename, const Program& program,
              const Domain& domain, Evidence& evidence, const DbOptions& options) {
  // Empty domains: a predicate over a type without constants cannot be grounded.
  for (const auto& p : program.predicates) {
    for (auto t : p.arg_types) {
      if (static_cast<std::size_t>(t) >= domain.num_types() || domain.size(t) == 0) {
        throw MlnError(filename + ": type '" + program.types[t] + "' has no constants (empty domain, needed by '" +
                       p.name + "')");
      }
    }
  }
  std::map<std::pair<std::int32_t, std::int64_t>, std::int32_t> given_at;  // atom -> line
  std::vector<std::int32_t> args;
  for_each_atom(text, filename, program,
                [&](const std::string& where, std::int32_t line_no, const ParsedAtom& atom, std::int32_t pred) {
    const auto& p = program.predicates[pred];
    if (p.query && !p.query_evidence_allowed && !options.allow_all_query_evidence) {
      throw MlnError(where + "'" + atom.name + "' is a query predicate; its atoms cannot be given as evidence");
    }
    args.clear();
    for (std::size_t i = 0; i < atom.args.size(); ++i) {
      const auto c = domain.find(p.arg_types[i], atom.args[i]);
      if (!c) {
        throw MlnError(where + "unknown constant '" + atom.args[i] + "' of type '" + program.types[p.arg_types[i]] +
                       "' (argument " + std::to_string(i + 1) + " of '" + atom.name + "')");
      }
      args.push_back(*c);
    }
    const auto flat = evidence.flat_index(pred, args);
    const auto old = evidence.get_flat(pred, flat);
    if (old != Evidence::kUnknown && (old != 0) != atom.value) {
      throw MlnError(where + "'" + atom.original + "' contradicts line " + std::to_string(given_at[{pred, flat}]) +
                     " (the same atom given true and false)");
    }
    given_at.emplace(std::make_pair(pred, flat), line_no);
    evidence.set_flat(pred, flat, atom.value ? 1 : 0);
  });
}

std::string read_text_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw MlnError(path + ": evidence file expected, this is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MlnError(path + ": cannot open evidence file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void read_db_file(const std::string& path, const Program& program, const Domain& domain, Evidence& evidence,
                  const DbOptions& options) {
  parse_db(read_text_file(path), path, program, domain, evidence, options);
}

}  // namespace ksmc::runtime::mln
