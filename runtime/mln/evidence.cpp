#include "runtime/mln/evidence.h"

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
  std::int32_t line_no = 0;
  std::size_t pos = 0;
  std::vector<std::int32_t> args;
  while (pos <= text.size()) {
    const auto nl = text.find('\n', pos);
    std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++line_no;
    const auto where = filename + ":" + std::to_string(line_no) + ": ";
    if (const auto c = line.find("//"); c != std::string_view::npos) line = line.substr(0, c);
    line = trim(line);
    if (line.empty()) continue;
    const std::string original(line);
    bool value = true;
    if (line.front() == '!') {
      value = false;
      line = trim(line.substr(1));
    }
    const auto open = line.find('(');
    if (open == std::string_view::npos || line.back() != ')') {
      throw MlnError(where + "malformed ground atom '" + original + "': expected name(arg, ...) or !name(arg, ...)");
    }
    const std::string name(trim(line.substr(0, open)));
    if (!valid_name(name)) {
      throw MlnError(where + "malformed ground atom '" + original + "': bad predicate name");
    }
    const auto pred = program.find_predicate(name);
    if (!pred) throw MlnError(where + "unknown predicate '" + name + "'");
    const auto& p = program.predicates[*pred];
    if (p.query && !p.query_evidence_allowed && !options.allow_all_query_evidence) {
      throw MlnError(where + "'" + name + "' is a query predicate; its atoms cannot be given as evidence");
    }
    std::vector<std::string> names;
    std::string_view inner = line.substr(open + 1, line.size() - open - 2);
    if (!trim(inner).empty()) {
      std::size_t s = 0;
      while (true) {
        const auto comma = inner.find(',', s);
        names.emplace_back(trim(inner.substr(s, comma == std::string_view::npos ? std::string_view::npos : comma - s)));
        if (comma == std::string_view::npos) break;
        s = comma + 1;
      }
    }
    for (const auto& n : names) {
      if (!valid_name(n)) {
        throw MlnError(where + "malformed ground atom '" + original + "': bad argument '" + n + "'");
      }
    }
    if (names.size() != p.arg_types.size()) {
      throw MlnError(where + "'" + name + "' takes " + std::to_string(p.arg_types.size()) + " argument" +
                     (p.arg_types.size() == 1 ? "" : "s") + ", got " + std::to_string(names.size()));
    }
    args.clear();
    for (std::size_t i = 0; i < names.size(); ++i) {
      const auto c = domain.find(p.arg_types[i], names[i]);
      if (!c) {
        throw MlnError(where + "unknown constant '" + names[i] + "' of type '" + program.types[p.arg_types[i]] +
                       "' (argument " + std::to_string(i + 1) + " of '" + name + "')");
      }
      args.push_back(*c);
    }
    const auto flat = evidence.flat_index(*pred, args);
    const auto old = evidence.get_flat(*pred, flat);
    if (old != Evidence::kUnknown && (old != 0) != value) {
      throw MlnError(where + "'" + original + "' contradicts line " +
                     std::to_string(given_at[{*pred, flat}]) + " (the same atom given true and false)");
    }
    given_at.emplace(std::make_pair(*pred, flat), line_no);
    evidence.set_flat(*pred, flat, value ? 1 : 0);
  }
}

void read_db_file(const std::string& path, const Program& program, const Domain& domain, Evidence& evidence,
                  const DbOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MlnError(path + ": cannot open evidence file");
  std::ostringstream ss;
  ss << in.rdbuf();
  parse_db(ss.str(), path, program, domain, evidence, options);
}

}  // namespace ksmc::runtime::mln
