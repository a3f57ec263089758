// Placing nlohmann::json errors in the text. A parse_error knows its byte, but a number
// overflow ("1e999", out_of_range.406) names neither file nor place; json_error_place()
// finds the number in the text so every JSON reader can say "scene.json:4:12: ...".
// Header-only: readers use it with their own error types.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace ksmc::runtime::io {

// "<line>:<column>" (1-based) of byte `offset` in `text`.
inline std::string text_place(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t line = 1;
  std::size_t column = 1;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

// "<file>:<line>:<column>: <what>" for any json::exception thrown by parse(text).
inline std::string json_error_message(const std::string& file, std::string_view text,
                                      const nlohmann::json::exception& e) {
  if (const auto* pe = dynamic_cast<const nlohmann::json::parse_error*>(&e)) {
    (void)pe;  // its message already gives "at line L, column C"
    return file + ": invalid JSON: " + e.what();
  }
  // out_of_range.406 "number overflow parsing '1e999'": locate the quoted number.
  const std::string what = e.what();
  const auto q1 = what.find('\'');
  const auto q2 = q1 == std::string::npos ? std::string::npos : what.find('\'', q1 + 1);
  if (e.id == 406 && q2 != std::string::npos) {
    const std::string number = what.substr(q1 + 1, q2 - q1 - 1);
    const auto at = text.find(number);
    return file + (at == std::string_view::npos ? std::string() : ":" + text_place(text, at)) + ": number " + number +
           " is out of the range of a double";
  }
  return file + ": invalid JSON: " + what;
}

}  // namespace ksmc::runtime::io
