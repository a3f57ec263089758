#include "compiler/build/loader.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "compiler/build/builder.h"
#include "compiler/parse/parser.h"

namespace ksmc::compiler::build {

namespace fs = std::filesystem;

bool read_file(const std::string& path, std::string& text, std::string& error) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    error = "is a directory";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = std::strerror(errno);
    return false;
  }
  // Read at most kMaxSourceBytes (+1 to notice more): /dev/zero or a huge file is refused
  // instead of exhausting memory.
  text.clear();
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSourceBytes) {
      error = "larger than " + std::to_string(kMaxSourceBytes / 1000000) + " MB (not a .ksm source?)";
      return false;
    }
  }
  return normalize_source(text, error);
}

bool normalize_source(std::string& text, std::string& error) {
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // UTF-8 byte order mark
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\0') {
      error = "NUL byte at line " + std::to_string(line) + ", column " + std::to_string(column) +
              " (a binary file, or UTF-16? sources must be UTF-8 text)";
      return false;
    }
    // A lone \r (old Mac line end) ends a line like \n; same length, so places stay.
    if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return true;
}

namespace {

std::string key_of(const std::string& path) {
  std::error_code ec;
  const fs::path c = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path : c.string();
}

// Candidate locations of `rel` included from `includer`.
std::vector<std::string> candidates(const std::string& includer, const std::string& rel, const LoadOptions& options) {
  std::vector<std::string> out;
  if (fs::path(rel).is_absolute()) {
    out.push_back(rel);
    return out;
  }
  fs::path dir = fs::path(includer).parent_path();
  std::error_code ec;
  const fs::path abs_dir = fs::absolute(dir.empty() ? fs::path(".") : dir, ec).lexically_normal();
  const auto levels = static_cast<int>(std::distance(abs_dir.begin(), abs_dir.end()));
  fs::path up = dir;
  for (int i = 0; i < levels; ++i) {
    out.push_back((up / rel).lexically_normal().string());
    up = up / "..";
  }
  for (const std::string& d : options.include_dirs) out.push_back((fs::path(d) / rel).lexically_normal().string());
  return out;
}

bool load_one(const std::string& path, std::string text, const LoadOptions& options, diag::SourceManager& sources,
              diag::DiagEngine& diags, ast::Program& out, std::set<std::string>& seen) {
  const int file = sources.add(path, text);
  const auto parsed = parse::parse_text(file, sources.text(file), diags);
  if (!parsed->ok) return false;
  ast::Module module = build_module(*parsed, path, diags);
  const bool built = diags.errors_in(file) == 0;
  std::vector<std::pair<std::string, ast::Loc>> includes;
  for (const ast::Item& item : module.items) {
    if (const auto* inc = std::get_if<ast::IncludeDecl>(&item.node)) includes.emplace_back(inc->path, inc->loc);
  }
  out.modules.push_back(std::move(module));
  bool ok = built;
  if (!options.follow_includes) return ok;
  for (const auto& [rel, loc] : includes) {
    std::string found;
    for (const std::string& cand : candidates(path, rel, options)) {
      std::error_code ec;
      if (fs::is_regular_file(cand, ec)) {
        found = cand;
        break;
      }
    }
    if (found.empty()) {
      diags.error(loc, "cannot find include file '" + rel + "'");
      ok = false;
      continue;
    }
    if (!seen.insert(key_of(found)).second) continue;  // each file once (also breaks cycles)
    std::string inc_text;
    std::string error;
    if (!read_file(found, inc_text, error)) {
      diags.error(loc, "cannot read include file '" + found + "': " + error);
      ok = false;
      continue;
    }
    ok = load_one(found, std::move(inc_text), options, sources, diags, out, seen) && ok;
  }
  return ok;
}

}  // namespace

bool load_program_text(const std::string& path, std::string text, const LoadOptions& options,
                       diag::SourceManager& sources, diag::DiagEngine& diags, ast::Program& out) {
  std::set<std::string> seen{key_of(path)};
  return load_one(path, std::move(text), options, sources, diags, out, seen);
}

bool load_program(const std::string& path, const LoadOptions& options, diag::SourceManager& sources,
                  diag::DiagEngine& diags, ast::Program& out) {
  std::string text;
  std::string error;
  if (!read_file(path, text, error)) {
    diags.error(ast::Loc{}, "cannot read '" + path + "': " + error);
    return false;
  }
  return load_program_text(path, std::move(text), options, sources, diags, out);
}

}  // namespace ksmc::compiler::build
