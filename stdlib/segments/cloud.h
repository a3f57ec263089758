// The point-cloud input of the segments kit: a text file with one point `x y` (metres) per
// line; `#` starts a comment (whole line or trailing); blank lines are skipped. Errors name
// the file and line: `cloud.txt:7: error: expected two numbers 'x y', got '1.0'`.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "stdlib/segments/geometry.h"

namespace ksmc::stdlib::segments {

class CloudError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::size_t kMaxPoints = 1000000;
inline constexpr double kMaxCoordinate = 1e6;  // metres

// Parses the text (`name` is used in messages). Throws CloudError: malformed line, a value
// that is not finite or beyond +-kMaxCoordinate, no point at all, more than kMaxPoints points.
std::vector<Vec2> parse_points(std::string_view text, const std::string& name);
// Reads and parses a file; a missing or unreadable file is a CloudError naming it.
std::vector<Vec2> load_points(const std::filesystem::path& path);

}  // namespace ksmc::stdlib::segments
