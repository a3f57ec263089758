#include "compiler/infer/db_diagnostics.h"

#include <map>
#include <string_view>

#include "compiler/check/pass.h"
#include "runtime/mln/error.h"

namespace ksmc::compiler::infer {
namespace {

namespace mln = ksmc::runtime::mln;

// The text between the first pair of single quotes after `marker` in `message`.
std::string quoted_after(const std::string& message, const std::string& marker) {
  const auto m = message.find(marker);
  if (m == std::string::npos) return {};
  const auto b = m + marker.size();
  const auto e = message.find('\'', b);
  return e == std::string::npos ? std::string{} : message.substr(b, e - b);
}

// Each line of `text` as its own piece: calls fn(line_no, line).
template <typename Fn>
void for_each_line(const std::string& text, Fn&& fn) {
  std::size_t pos = 0;
  std::int32_t line_no = 0;
  while (pos <= text.size()) {
    const auto nl = text.find('\n', pos);
    const auto end = nl == std::string::npos ? text.size() : nl;
    fn(++line_no, std::string_view(text).substr(pos, end - pos));
    pos = end + 1;
  }
}

// "path:1: msg" (the runtime's message for a one-line text) -> "path:N: msg".
std::string relocate(const std::string& message, const std::string& path, std::int32_t line_no) {
  const std::string one = path + ":1: ";
  if (message.rfind(one, 0) != 0) return message;
  return path + ":" + std::to_string(line_no) + ": " + message.substr(one.size());
}

// The atom of a line without its sign, blanks and comment: the key for contradictions.
std::string atom_key(std::string_view line) {
  if (const auto c = line.find("//"); c != std::string_view::npos) line = line.substr(0, c);
  std::string key;
  for (char ch : line)
    if (ch != ' ' && ch != '\t' && ch != '\r') key.push_back(ch);
  if (!key.empty() && key.front() == '!') key.erase(0, 1);
  return key;
}

}  // namespace

std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string best = check::suggest(word, candidates);
  return best.empty() ? std::string{} : " (did you mean '" + best + "'?)";
}

std::string with_error_tag(const std::string& m, const std::string& path, const std::string& tool) {
  const std::string prefix = path + ":";
  std::size_t colon = std::string::npos;
  if (m.rfind(prefix, 0) == 0) colon = m.find(": ", prefix.size() - 1);
  if (colon != std::string::npos) return m.substr(0, colon) + ": error: " + m.substr(colon + 2);
  return tool + ": error: " + m;
}

void collect_constants_lenient(const std::string& text, const std::string& path, const mln::Program& program,
                               mln::Domain& domain) {
  for_each_line(text, [&](std::int32_t, std::string_view line) {
    try {
      mln::collect_db_constants(line, path, program, domain);
    } catch (const mln::MlnError&) {
      // reported by parse_db_all
    }
  });
}

std::vector<std::string> parse_db_all(const std::string& text, const std::string& path, const mln::Program& program,
                                      const mln::Domain& domain, mln::Evidence& evidence,
                                      const mln::DbOptions& options) {
  std::vector<std::string> errors;
  // Whole-file errors (NUL bytes, an empty domain): report them once.
  try {
    mln::check_db_text(text, path);
    mln::parse_db("", path, program, domain, evidence, options);
  } catch (const mln::MlnError& e) {
    return {e.what()};
  }
  std::vector<std::string> predicate_names;
  for (const auto& p : program.predicates) predicate_names.push_back(p.name);
  std::map<std::string, std::int32_t> first_line;  // atom -> line that gave it
  for_each_line(text, [&](std::int32_t line_no, std::string_view line) {
    try {
      mln::parse_db(line, path, program, domain, evidence, options);
      first_line.emplace(atom_key(line), line_no);
    } catch (const mln::MlnError& e) {
      std::string m = relocate(e.what(), path, line_no);
      if (const auto at = m.find("contradicts line 0"); at != std::string::npos) {
        m.replace(at, 18, "contradicts line " + std::to_string(first_line[atom_key(line)]));
      } else if (const auto pred = quoted_after(m, "unknown predicate '"); !pred.empty()) {
        m += did_you_mean(pred, predicate_names);
      } else if (const auto c = quoted_after(m, "unknown constant '"); !c.empty()) {
        const auto type = program.find_type(quoted_after(m, "of type '"));
        if (type) m += did_you_mean(c, domain.constants(*type));
      }
      errors.push_back(m);
    }
  });
  return errors;
}

}  // namespace ksmc::compiler::infer
