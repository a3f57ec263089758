// Files embedded in the page as data: URIs (base64), so the page needs no other file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace ksmc::runtime::report {

std::string base64(std::string_view bytes);

// "data:<mime>;base64,..." of the file, or nullopt when it is absent or larger than
// max_bytes (a huge overlay would make the page slow to open). Throws naming the file
// when it exists but cannot be read.
std::optional<std::string> file_data_uri(const std::filesystem::path& path, std::string_view mime,
                                         std::size_t max_bytes);

}  // namespace ksmc::runtime::report
