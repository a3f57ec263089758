#include "stdlib/tabletop/perception/cloud_io.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "runtime/io/atomic_file.h"

namespace ksmc::stdlib::tabletop::perception {

Units parse_units(std::string_view text) {
  if (text == "m") return Units::m;
  if (text == "cm") return Units::cm;
  if (text == "mm") return Units::mm;
  throw std::invalid_argument(fmt::format("unknown cloud unit \"{}\" (expected cm, mm or m)", text));
}

double metres_per_unit(Units units) {
  switch (units) {
    case Units::cm: return 0.01;
    case Units::mm: return 0.001;
    case Units::m: break;
  }
  return 1.0;
}


// ---- The readers. Own parsers for the PLY and PCD subsets a depth sensor or PCL writes
// (PCL's readers trust the header: a huge element count allocates gigabytes, a truncated
// binary body or a bad header aborts; fuzz_cloud, docs/reliability.md). Every count and
// size in a header is checked against the bytes that follow before anything is
// allocated, and every error names the file and the place: a header line, a body line
// (ASCII), a byte offset (binary) or a point.
namespace {

// A numeric type of a PLY property or PCD field.
struct Scalar {
  std::size_t size = 0;
  char kind = 'F';  // 'I' signed, 'U' unsigned, 'F' floating
};

bool ply_scalar(std::string_view t, Scalar& s) {
  static const std::pair<std::string_view, Scalar> kTypes[] = {
      {"char", {1, 'I'}},   {"int8", {1, 'I'}},    {"uchar", {1, 'U'}},  {"uint8", {1, 'U'}},
      {"short", {2, 'I'}},  {"int16", {2, 'I'}},   {"ushort", {2, 'U'}}, {"uint16", {2, 'U'}},
      {"int", {4, 'I'}},    {"int32", {4, 'I'}},   {"uint", {4, 'U'}},   {"uint32", {4, 'U'}},
      {"float", {4, 'F'}},  {"float32", {4, 'F'}}, {"double", {8, 'F'}}, {"float64", {8, 'F'}}};
  for (const auto& [n, v] : kTypes)
    if (t == n) { s = v; return true; }
  return false;
}

// The value of a binary scalar at `p` (host little endian; `swap` for big-endian data).
double binary_value(const char* p, Scalar s, bool swap) {
  unsigned char b[8];
  std::memcpy(b, p, s.size);
  if (swap) std::reverse(b, b + s.size);
  switch (s.kind) {
    case 'F': {
      if (s.size == 4) { float f; std::memcpy(&f, b, 4); return f; }
      double d; std::memcpy(&d, b, 8); return d;
    }
    case 'I': {
      if (s.size == 1) { std::int8_t v; std::memcpy(&v, b, 1); return v; }
      if (s.size == 2) { std::int16_t v; std::memcpy(&v, b, 2); return v; }
      if (s.size == 4) { std::int32_t v; std::memcpy(&v, b, 4); return v; }
      std::int64_t v; std::memcpy(&v, b, 8); return static_cast<double>(v);
    }
    default: {
      if (s.size == 1) return b[0];
      if (s.size == 2) { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
      if (s.size == 4) { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
      std::uint64_t v; std::memcpy(&v, b, 8); return static_cast<double>(v);
    }
  }
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t b = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

// A non-negative decimal count, at most `limit`.
bool count_of(std::string_view t, std::uint64_t limit, std::uint64_t& n) {
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
  return ec == std::errc() && end == t.data() + t.size() && n <= limit;
}

// A decimal number, "nan" and "inf" included (an optional leading '+').
bool number_of(std::string_view t, double& v) {
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  return ec == std::errc() && end == t.data() + t.size();
}

// Header lines one by one ('\n' or "\r\n"), with their numbers.
class Lines {
 public:
  explicit Lines(std::string_view bytes) : bytes_(bytes) {}
  bool next(std::string_view& line) {
    if (pos_ >= bytes_.size()) return false;
    const std::size_t eol = bytes_.find('\n', pos_);
    line = bytes_.substr(pos_, eol == std::string_view::npos ? std::string_view::npos : eol - pos_);
    pos_ = eol == std::string_view::npos ? bytes_.size() : eol + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++number_;
    return true;
  }
  [[nodiscard]] std::size_t number() const { return number_; }
  [[nodiscard]] std::size_t offset() const { return pos_; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

// The whitespace-separated tokens of an ASCII body, with their line numbers.
class Tokens {
 public:
  Tokens(std::string_view body, std::size_t first_line) : body_(body), line_(first_line) {}
  bool next(std::string_view& token) {
    while (pos_ < body_.size() && std::isspace(static_cast<unsigned char>(body_[pos_]))) {
      if (body_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ >= body_.size()) return false;
    const std::size_t b = pos_;
    while (pos_ < body_.size() && !std::isspace(static_cast<unsigned char>(body_[pos_]))) ++pos_;
    token = body_.substr(b, pos_ - b);
    return true;
  }
  [[nodiscard]] std::size_t line() const { return line_; }

 private:
  std::string_view body_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

[[noreturn]] void fail(const std::string& file, const std::string& what) {
  throw CloudError(fmt::format("{}: {}", file, what));
}

// ---- PLY: ascii, binary_little_endian, binary_big_endian; the x, y, z properties of the
// first `vertex` element; other elements (faces, lists) are read past.
struct PlyProperty {
  std::string name;
  Scalar type;
  bool list = false;
  Scalar count_type;
};
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::size_t line = 0;
  std::vector<PlyProperty> props;
};

std::vector<double> read_ply(std::string_view bytes, const std::string& file) {
  Lines lines(bytes);
  std::string_view line;
  if (!lines.next(line) || line != "ply") fail(file, "header line 1: not a PLY file (the first line must be \"ply\")");
  std::string format;
  std::vector<PlyElement> elements;
  bool ended = false;
  while (!ended && lines.next(line)) {
    const auto w = words(line);
    const std::string at = fmt::format("header line {}", lines.number());
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") {
      ended = true;
    } else if (w[0] == "format") {
      if (w.size() != 3 || (w[1] != "ascii" && w[1] != "binary_little_endian" && w[1] != "binary_big_endian") ||
          w[2] != "1.0")
        fail(file, at + ": expected \"format ascii|binary_little_endian|binary_big_endian 1.0\"");
      format = std::string(w[1]);
    } else if (w[0] == "element") {
      PlyElement e;
      if (w.size() != 3 || !count_of(w[2], bytes.size(), e.count))
        fail(file, fmt::format("{}: expected \"element <name> <count>\" with a count of at most the file size ({} bytes)",
                               at, bytes.size()));
      e.name = std::string(w[1]);
      e.line = lines.number();
      elements.push_back(std::move(e));
    } else if (w[0] == "property") {
      if (elements.empty()) fail(file, at + ": a property before any element");
      PlyProperty p;
      const bool list = w.size() == 5 && w[1] == "list";
      if (list ? !ply_scalar(w[2], p.count_type) || p.count_type.kind == 'F' || !ply_scalar(w[3], p.type)
               : w.size() != 3 || !ply_scalar(w[1], p.type))
        fail(file, at + ": expected \"property <type> <name>\" or \"property list <integer type> <type> <name>\"");
      p.list = list;
      p.name = std::string(w.back());
      elements.back().props.push_back(std::move(p));
    } else {
      fail(file, fmt::format("{}: unknown header keyword \"{}\"", at, w[0]));
    }
  }
  if (!ended) fail(file, "no \"end_header\" line");
  if (format.empty()) fail(file, "no \"format\" line in the header");
  const PlyElement* vertex = nullptr;
  std::size_t axis[3] = {0, 0, 0};
  for (const auto& e : elements) {
    if (e.props.empty()) fail(file, fmt::format("header line {}: element \"{}\" has no properties", e.line, e.name));
    if (e.name != "vertex" || vertex) continue;
    vertex = &e;
    for (int k = 0; k < 3; ++k) {
      const char* n = k == 0 ? "x" : k == 1 ? "y" : "z";
      const auto it = std::find_if(e.props.begin(), e.props.end(), [&](const PlyProperty& p) { return p.name == n; });
      if (it == e.props.end() || it->list)
        fail(file, fmt::format("header line {}: element vertex has no scalar property \"{}\"", e.line, n));
      axis[k] = static_cast<std::size_t>(it - e.props.begin());
    }
  }
  if (!vertex) fail(file, "no \"element vertex\" in the header");

  const std::string_view body = bytes.substr(lines.offset());
  std::vector<double> xyz;
  std::vector<double> record;
  if (format == "ascii") {
    Tokens tokens(body, lines.number() + 1);
    for (const auto& e : elements) {
      // Each record needs at least two bytes (a token and a separator) per property.
      if (e.count > body.size() / (2 * e.props.size()) + 1)
        fail(file, fmt::format("header line {}: {} {} elements cannot fit in the {} bytes after the header", e.line,
                               e.count, e.name, body.size()));
      if (&e == vertex) xyz.reserve(3 * e.count);
      for (std::uint64_t i = 0; i < e.count; ++i) {
        record.clear();
        for (const auto& p : e.props) {
          std::uint64_t n = 1;
          std::string_view t;
          if (p.list) {
            if (!tokens.next(t)) break;
            if (!count_of(t, body.size(), n))
              fail(file, fmt::format("line {}: {} {}: bad list length \"{}\"", tokens.line(), e.name, i, t));
          }
          for (std::uint64_t j = 0; j < n; ++j) {
            double v = 0;
            if (!tokens.next(t))
              fail(file, fmt::format("the body ends in {} {} of {} (header line {})", e.name, i, e.count, e.line));
            if (!number_of(t, v))
              fail(file, fmt::format("line {}: {} {}: \"{}\" is not a number in range", tokens.line(), e.name, i, t));
            if (!p.list) record.push_back(v);
          }
          if (p.list) record.push_back(0);
        }
        if (record.size() != e.props.size())
          fail(file, fmt::format("the body ends in {} {} of {} (header line {})", e.name, i, e.count, e.line));
        if (&e == vertex)
          for (const std::size_t k : axis) xyz.push_back(record[k]);
      }
    }
    return xyz;
  }
  const bool swap = format == "binary_big_endian";
  std::size_t pos = 0;
  for (const auto& e : elements) {
    std::size_t least = 0;  // bytes of one record without the list items
    for (const auto& p : e.props) least += p.list ? p.count_type.size : p.type.size;
    if (e.count > (body.size() - pos) / least)
      fail(file, fmt::format("header line {}: {} {} elements of at least {} bytes need {} bytes, the file has {} left "
                             "(truncated?)",
                             e.line, e.count, e.name, least, e.count * least, body.size() - pos));
    if (&e == vertex) xyz.reserve(3 * e.count);
    for (std::uint64_t i = 0; i < e.count; ++i) {
      record.clear();
      for (const auto& p : e.props) {
        const Scalar head = p.list ? p.count_type : p.type;
        if (body.size() - pos < head.size)
          fail(file, fmt::format("byte {}: the body ends in {} {} of {} (truncated?)", lines.offset() + pos, e.name, i,
                                 e.count));
        const double v = binary_value(body.data() + pos, head, swap);
        pos += head.size;
        if (!p.list) { record.push_back(v); continue; }
        if (v < 0 || v > static_cast<double>((body.size() - pos) / p.type.size))
          fail(file, fmt::format("byte {}: {} {}: list length {} does not fit in the file", lines.offset() + pos,
                                 e.name, i, v));
        pos += static_cast<std::size_t>(v) * p.type.size;
        record.push_back(0);
      }
      if (&e == vertex)
        for (const std::size_t k : axis) xyz.push_back(record[k]);
    }
  }
  return xyz;
}

// ---- PCD (v0.5-0.7): DATA ascii, binary and binary_compressed (LZF); fields x, y, z of
// any numeric type; other fields (rgb, normals, padding) are read past.

// LZF decompression (the format PCL writes): exactly `out.size()` bytes from `in`, every
// back reference and run checked. False on a corrupt stream.
bool lzf_decompress(std::string_view in, std::string& out) {
  std::size_t ip = 0, op = 0;
  while (ip < in.size()) {
    const unsigned ctrl = static_cast<unsigned char>(in[ip++]);
    if (ctrl < 32) {  // a literal run of ctrl + 1 bytes
      const std::size_t len = ctrl + 1;
      if (len > in.size() - ip || len > out.size() - op) return false;
      std::memcpy(out.data() + op, in.data() + ip, len);
      ip += len;
      op += len;
      continue;
    }
    std::size_t len = ctrl >> 5;  // a back reference of len + 2 bytes
    if (len == 7) {
      if (ip >= in.size()) return false;
      len += static_cast<unsigned char>(in[ip++]);
    }
    if (ip >= in.size()) return false;
    const std::size_t back = ((ctrl & 0x1fU) << 8) + static_cast<unsigned char>(in[ip++]) + 1;
    len += 2;
    if (back > op || len > out.size() - op) return false;
    for (std::size_t k = 0; k < len; ++k, ++op) out[op] = out[op - back];
  }
  return op == out.size();
}

// `organised`: HEIGHT > 1, an image-shaped cloud (PCL marks its missing returns with NaN).
std::vector<double> read_pcd(std::string_view bytes, const std::string& file, bool& organised) {
  Lines lines(bytes);
  std::string_view line;
  std::vector<std::string_view> fields, sizes, types, counts;
  std::uint64_t width = 0, height = 1, points = 0;
  bool has_width = false, has_points = false;
  std::string data;
  std::size_t fields_line = 0;
  while (data.empty() && lines.next(line)) {
    const auto w = words(line);
    if (w.empty() || w[0].front() == '#') continue;
    const std::string at = fmt::format("header line {}", lines.number());
    const std::vector<std::string_view> rest(w.begin() + 1, w.end());
    // A compressed body may hold more points than it has bytes (LZF: up to 88 times more).
    const std::uint64_t limit = 100 * static_cast<std::uint64_t>(bytes.size()) + 100;
    auto one_count = [&](std::uint64_t& n) {
      if (rest.size() != 1 || !count_of(rest[0], limit, n))
        fail(file, fmt::format("{}: {} expects one count of at most {} (100 x the file size)", at, w[0], limit));
    };
    if (w[0] == "VERSION" || w[0] == "VIEWPOINT") continue;
    if (w[0] == "FIELDS" || w[0] == "COLUMNS") { fields = rest; fields_line = lines.number(); }
    else if (w[0] == "SIZE") sizes = rest;
    else if (w[0] == "TYPE") types = rest;
    else if (w[0] == "COUNT") counts = rest;
    else if (w[0] == "WIDTH") { one_count(width); has_width = true; }
    else if (w[0] == "HEIGHT") one_count(height);
    else if (w[0] == "POINTS") { one_count(points); has_points = true; }
    else if (w[0] == "DATA") {
      if (rest.size() != 1 || (rest[0] != "ascii" && rest[0] != "binary" && rest[0] != "binary_compressed"))
        fail(file, at + ": expected \"DATA ascii|binary|binary_compressed\"");
      data = std::string(rest[0]);
    } else {
      fail(file, fmt::format("{}: unknown header keyword \"{}\" (not a PCD file?)", at, w[0]));
    }
  }
  if (data.empty()) fail(file, "no \"DATA\" line in the header (not a PCD file?)");
  if (fields.empty()) fail(file, "no \"FIELDS\" line in the header");
  const std::string at = fmt::format("header line {}", fields_line);
  if (sizes.size() != fields.size() || types.size() != fields.size() || (!counts.empty() && counts.size() != fields.size()))
    fail(file, fmt::format("{}: {} fields, but SIZE, TYPE and COUNT give {}, {} and {} entries", at, fields.size(),
                           sizes.size(), types.size(), counts.empty() ? fields.size() : counts.size()));
  std::uint64_t area = 0;
  if (__builtin_mul_overflow(width, height, &area)) fail(file, fmt::format("WIDTH {} x HEIGHT {} overflows", width, height));
  if (!has_points) points = area;
  if (!has_width && !has_points) fail(file, "neither WIDTH nor POINTS in the header");
  if (has_width && has_points && area != points)
    fail(file, fmt::format("WIDTH {} x HEIGHT {} is not POINTS {}", width, height, points));
  organised = height > 1;

  std::vector<Scalar> scalar(fields.size());
  std::vector<std::uint64_t> count(fields.size(), 1);
  std::vector<std::size_t> offset(fields.size());  // within a record (binary) or a field block (compressed)
  std::size_t record = 0, values = 0;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    std::uint64_t size = 0;
    if (!count_of(sizes[f], 8, size) || (size != 1 && size != 2 && size != 4 && size != 8) || types[f].size() != 1 ||
        std::string_view("IUF").find(types[f][0]) == std::string_view::npos || (types[f][0] == 'F' && size < 4) ||
        (!counts.empty() && (!count_of(counts[f], 1U << 20, count[f]) || count[f] == 0)))
      fail(file, fmt::format("{}: field \"{}\": SIZE {} TYPE {} COUNT {} is not a valid numeric field", at, fields[f],
                             sizes[f], types[f], counts.empty() ? "1" : counts[f]));
    scalar[f] = Scalar{static_cast<std::size_t>(size), types[f][0]};
    offset[f] = record;
    record += scalar[f].size * count[f];
    values += count[f];
  }
  std::size_t axis[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const std::string_view n = k == 0 ? "x" : k == 1 ? "y" : "z";
    const auto it = std::find(fields.begin(), fields.end(), n);
    if (it == fields.end()) fail(file, fmt::format("{}: no field \"{}\"", at, n));
    axis[k] = static_cast<std::size_t>(it - fields.begin());
  }

  const std::string_view body = bytes.substr(lines.offset());
  std::vector<double> xyz;
  if (data == "ascii") {
    if (points > body.size() / (2 * values) + 1)
      fail(file, fmt::format("{} points of {} values cannot fit in the {} bytes after the header", points, values,
                             body.size()));
    xyz.reserve(3 * points);
    Tokens tokens(body, lines.number() + 1);
    std::vector<double> row(fields.size());
    for (std::uint64_t i = 0; i < points; ++i) {
      for (std::size_t f = 0; f < fields.size(); ++f)
        for (std::uint64_t j = 0; j < count[f]; ++j) {
          std::string_view t;
          double v = 0;
          if (!tokens.next(t)) fail(file, fmt::format("the body ends in point {} of {}", i, points));
          if (!number_of(t, v))
            fail(file, fmt::format("line {}: point {}: \"{}\" is not a number in range", tokens.line(), i, t));
          if (j == 0) row[f] = v;
        }
      for (const std::size_t k : axis) xyz.push_back(row[k]);
    }
    return xyz;
  }
  std::string unpacked;
  std::string_view raw = body;
  const bool compressed = data == "binary_compressed";
  if (points > body.size() / record && !compressed)
    fail(file, fmt::format("{} points of {} bytes need {} bytes, the file has {} after the header (truncated?)", points,
                           record, points * record, body.size()));
  if (compressed) {
    if (body.size() < 8) fail(file, "binary_compressed body shorter than its 8-byte size header (truncated?)");
    std::uint32_t packed = 0, size = 0;
    std::memcpy(&packed, body.data(), 4);
    std::memcpy(&size, body.data() + 4, 4);
    if (packed > body.size() - 8)
      fail(file, fmt::format("byte {}: compressed size {} exceeds the {} bytes that follow (truncated?)",
                             lines.offset(), packed, body.size() - 8));
    if (points > std::numeric_limits<std::uint32_t>::max() / record || size != points * record)
      fail(file, fmt::format("byte {}: uncompressed size {} is not {} points x {} bytes", lines.offset() + 4, size,
                             points, record));
    // LZF expands at most 88-fold (264 bytes from a 3-byte back reference).
    if (size / 88 > packed + 1)
      fail(file, fmt::format("byte {}: {} compressed bytes cannot hold {} bytes", lines.offset(), packed, size));
    unpacked.resize(size);
    if (!lzf_decompress(body.substr(8, packed), unpacked))
      fail(file, fmt::format("byte {}: corrupt compressed data", lines.offset() + 8));
    raw = unpacked;
  }
  xyz.reserve(3 * points);
  for (std::uint64_t i = 0; i < points; ++i)
    for (const std::size_t k : axis) {
      // binary: records one after another; compressed: each field's values for all points.
      const std::size_t at_byte = compressed ? offset[k] * points + i * scalar[k].size * count[k] : i * record + offset[k];
      xyz.push_back(binary_value(raw.data() + at_byte, scalar[k], false));
    }
  return xyz;
}
}  // namespace

Points load_cloud(const std::filesystem::path& path, Units units, std::size_t* missing_returns) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw CloudError(fmt::format("{}: cannot open file", name));
  if (!std::filesystem::is_regular_file(status))  // a folder, /dev/zero, a pipe: never opened nor read to the end
    throw CloudError(fmt::format("{}: expected a regular file", name));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CloudError(fmt::format("{}: cannot open file", name));
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".ply" && ext != ".pcd")
    throw CloudError(fmt::format("{}: unknown cloud format \"{}\" (expected .ply or .pcd)", name, ext));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in && !in.eof()) throw CloudError(fmt::format("{}: cannot read file", name));
  const std::string bytes = std::move(buffer).str();
  bool organised = false;
  const std::vector<double> xyz = ext == ".ply" ? read_ply(bytes, name) : read_pcd(bytes, name, organised);
  if (xyz.empty()) throw CloudError(fmt::format("{}: empty cloud: no points", name));

  const double scale = metres_per_unit(units);
  Points out;
  out.reserve(xyz.size() / 3);
  std::size_t missing = 0;
  for (std::size_t i = 0; i < xyz.size() / 3; ++i) {
    const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
    // A missing return: (0, 0, 0) from a depth camera, or a point that is NaN in x, y and z
    // in an organised PCD (PCL's convention, `is_dense` false). Anything else not finite is
    // a corrupt point.
    const bool no_return = (x == 0.0 && y == 0.0 && z == 0.0) ||
                           (organised && std::isnan(x) && std::isnan(y) && std::isnan(z));
    if (no_return) {
      ++missing;
      continue;
    }
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
      throw CloudError(fmt::format("{}: point {}: not a finite coordinate ({}, {}, {}){}", name, i, x, y, z,
                                   std::isnan(x) && std::isnan(y) && std::isnan(z)
                                       ? " (NaN marks a missing return only in an organised PCD, HEIGHT > 1)"
                                       : ""));
    out.emplace_back(scale * x, scale * y, scale * z);
  }
  if (out.empty())
    throw CloudError(fmt::format("{}: empty cloud: all {} points are missing returns (at (0, 0, 0) or NaN)", name, missing));
  if (missing_returns != nullptr) *missing_returns = missing;
  return out;
}

std::string ply_text(const Points& points) {
  std::string s = fmt::format(
      "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
      points.size());
  for (const auto& p : points) s += fmt::format("{:.6f} {:.6f} {:.6f}\n", p.x(), p.y(), p.z());
  return s;
}

void save_ply(const std::filesystem::path& path, const Points& points) {
  runtime::io::write_file_atomic(path, ply_text(points));
}

}  // namespace ksmc::stdlib::tabletop::perception
