#include "compiler/parse/prescan.h"

#include <cstdio>
#include <string>

#include "compiler/diag/utf8.h"

namespace ksmc::compiler::parse {

namespace {

// Walks the text keeping line/column (columns count code points).
class Cursor {
 public:
  Cursor(int file, std::string_view text) : file_(file), text_(text) {}
  [[nodiscard]] bool done() const { return pos_ >= text_.size(); }
  [[nodiscard]] char peek(std::size_t k = 0) const { return pos_ + k < text_.size() ? text_[pos_ + k] : '\0'; }
  [[nodiscard]] ast::Loc loc() const { return ast::Loc{file_, line_, col_, pos_}; }
  void advance() {
    const std::size_t n = diag::utf8_sequence_length(text_, pos_);
    if (text_[pos_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    pos_ += n == 0 ? 1 : n;
  }

 private:
  int file_;
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
};

bool ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

bool check_encoding(int file, std::string_view text, diag::DiagEngine& diags) {
  Cursor cur(file, text);
  std::size_t pos = 0;
  while (!cur.done()) {
    if (text[pos] == '\0') {
      diags.error(cur.loc(), "NUL byte in source: this does not look like a text file");
      return false;
    }
    const std::size_t n = diag::utf8_sequence_length(text, pos);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[pos])));
      diags.error(cur.loc(), std::string("invalid UTF-8 byte ") + hex + " (source files must be UTF-8)");
      return false;
    }
    cur.advance();
    pos += n;
  }
  return true;
}

}  // namespace

bool prescan(int file, std::string_view text, diag::DiagEngine& diags, const PrescanLimits& limits) {
  if (!check_encoding(file, text, diags)) return false;
  Cursor cur(file, text);
  int brackets = 0;
  int prefix = 0;  // '!' and 'exists' since the last statement end
  char prev = '\0';
  while (!cur.done()) {
    const char c = cur.peek();
    if (c == '/' && cur.peek(1) == '/') {
      while (!cur.done() && cur.peek() != '\n') cur.advance();
      continue;
    }
    if (c == '/' && cur.peek(1) == '*') {
      const ast::Loc start = cur.loc();
      cur.advance();
      cur.advance();
      while (!cur.done() && !(cur.peek() == '*' && cur.peek(1) == '/')) cur.advance();
      if (cur.done()) {
        diags.error(start, "unterminated comment: '/*' without '*/'");
        return false;
      }
      cur.advance();
      cur.advance();
      continue;
    }
    if (c == '"') {
      const ast::Loc start = cur.loc();
      cur.advance();
      while (!cur.done() && cur.peek() != '"' && cur.peek() != '\n') {
        if (cur.peek() == '\\' && cur.peek(1) != '\n' && cur.peek(1) != '\0') cur.advance();
        cur.advance();
      }
      if (cur.peek() != '"') {
        diags.error(start, "unterminated string literal");
        return false;
      }
      cur.advance();
      prev = '"';
      continue;
    }
    bool deeper = false;
    if (c == '(' || c == '[' || c == '{') {
      ++brackets;
      deeper = true;
    } else if (c == ')' || c == ']' || c == '}') {
      if (brackets > 0) --brackets;
    } else if (c == '!') {
      ++prefix;
      deeper = true;
    } else if (c == ';' || c == '.') {
      prefix = 0;
    } else if (c == 'e' && !ident_char(prev) && cur.peek(1) == 'x' && cur.peek(2) == 'i' && cur.peek(3) == 's' &&
               cur.peek(4) == 't' && cur.peek(5) == 's' && !ident_char(cur.peek(6))) {
      ++prefix;
      deeper = true;
    }
    if (deeper && brackets + prefix > limits.max_depth) {
      diags.error(cur.loc(), "nesting too deep: more than " + std::to_string(limits.max_depth) +
                                 " levels of brackets, '!' and 'exists'");
      return false;
    }
    prev = c;
    cur.advance();
  }
  if (text.size() > limits.max_bytes) {
    diags.error(ast::Loc{file, 1, 1, 0}, "file too large: " + std::to_string(text.size()) +
                                             " bytes (the limit is " + std::to_string(limits.max_bytes) + ")");
    return false;
  }
  return true;
}

}  // namespace ksmc::compiler::parse
