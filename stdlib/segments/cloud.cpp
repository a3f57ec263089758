#include "stdlib/segments/cloud.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ksmc::stdlib::segments {

namespace {

std::string_view trim(std::string_view s) {
  const char* ws = " \t\r\v\f";
  const auto b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  const auto e = s.find_last_not_of(ws);
  return s.substr(b, e - b + 1);
}

[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what) {
  throw CloudError(name + ":" + std::to_string(line) + ": error: " + what);
}

// Splits on blanks into at most 3 fields (a third means too many).
std::vector<std::string_view> fields(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size() && out.size() < 3) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == ',')) ++i;
    if (i >= s.size()) break;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != ',') ++j;
    out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

bool to_double(std::string_view f, double& v) {
  if (!f.empty() && f.front() == '+') f.remove_prefix(1);
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v);
  return r.ec == std::errc() && r.ptr == f.data() + f.size();
}

}  // namespace

std::vector<Vec2> parse_points(std::string_view text, const std::string& name) {
  std::vector<Vec2> pts;
  std::size_t line_no = 0, pos = 0;
  while (pos < text.size()) {
    auto nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    pos = nl + 1;
    ++line_no;
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    line = trim(line);
    if (line.empty()) continue;
    if (line.find('\0') != std::string_view::npos) fail(name, line_no, "binary data (NUL byte); expected text 'x y'");
    const auto f = fields(line);
    if (f.size() != 2)
      fail(name, line_no, "expected two numbers 'x y' (metres), got '" + std::string(line.substr(0, 60)) + "'");
    double x = 0.0, y = 0.0;
    if (!to_double(f[0], x)) fail(name, line_no, "'" + std::string(f[0].substr(0, 40)) + "' is not a number");
    if (!to_double(f[1], y)) fail(name, line_no, "'" + std::string(f[1].substr(0, 40)) + "' is not a number");
    if (!std::isfinite(x) || !std::isfinite(y)) fail(name, line_no, "coordinates must be finite (no nan or inf)");
    if (std::abs(x) > kMaxCoordinate || std::abs(y) > kMaxCoordinate)
      fail(name, line_no, "coordinates must be within +-1e6 m");
    if (pts.size() >= kMaxPoints) fail(name, line_no, "more than " + std::to_string(kMaxPoints) + " points");
    pts.push_back({x, y});
  }
  if (pts.empty()) throw CloudError(name + ": error: the point cloud is empty (no 'x y' line)");
  return pts;
}

std::vector<Vec2> load_points(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CloudError(path.string() + ": error: cannot open the point cloud file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw CloudError(path.string() + ": error: cannot read the point cloud file");
  return parse_points(ss.str(), path.string());
}

}  // namespace ksmc::stdlib::segments
