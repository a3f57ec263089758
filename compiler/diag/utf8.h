// Minimal UTF-8 validation shared by the pre-scan and the diagnostics printer.
#pragma once

#include <cstddef>
#include <string_view>

namespace ksmc::compiler::diag {

// Length in bytes of the well-formed UTF-8 sequence starting at s[i], or 0 when the bytes
// there are not well-formed UTF-8 (overlong forms, surrogates and values past U+10FFFF are
// rejected as in RFC 3629).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i);

}  // namespace ksmc::compiler::diag
