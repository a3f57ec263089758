#include "stdlib/indoor/io/image_file.h"

#include <cerrno>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "stdlib/indoor/io/map_error.h"
#include "stdlib/indoor/io/occupancy_map.h"

namespace ksmc::stdlib::indoor::io {

namespace fs = std::filesystem;

namespace {

// Reads at most `limit` bytes (all of the file when limit == 0).
std::string read_bytes(const fs::path& path, std::size_t limit) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw MapLoadError(MapErrorKind::Unreadable, path, 0, "file does not exist");
  }
  if (fs::is_directory(path, ec)) {
    throw MapLoadError(MapErrorKind::Unreadable, path, 0, "is a directory, not a file");
  }
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    throw MapLoadError(MapErrorKind::Unreadable, path, 0,
                       std::string("cannot open: ") + std::strerror(errno));
  }
  std::string out;
  char buf[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) {
    out.append(buf, n);
    if (limit > 0 && out.size() >= limit) {
      out.resize(limit);
      break;
    }
  }
  const bool failed = std::ferror(f) != 0;
  const int saved = errno;
  std::fclose(f);
  if (failed) {
    throw MapLoadError(MapErrorKind::Unreadable, path, 0,
                       std::string("read error: ") + std::strerror(saved));
  }
  return out;
}

}  // namespace

std::string read_file_bytes(const fs::path& path) { return read_bytes(path, 0); }

namespace {

constexpr unsigned char kPngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool is_png(std::string_view b) {
  return b.size() >= 8 && std::memcmp(b.data(), kPngMagic, 8) == 0;
}

std::uint32_t be32(std::string_view b, std::size_t at) {
  return (std::uint32_t(static_cast<unsigned char>(b[at])) << 24) |
         (std::uint32_t(static_cast<unsigned char>(b[at + 1])) << 16) |
         (std::uint32_t(static_cast<unsigned char>(b[at + 2])) << 8) |
         std::uint32_t(static_cast<unsigned char>(b[at + 3]));
}

std::string describe_first_bytes(std::string_view b) {
  std::string out;
  const std::size_t n = std::min<std::size_t>(b.size(), 8);
  char tmp[4];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(tmp, sizeof tmp, "%02x", static_cast<unsigned>(static_cast<unsigned char>(b[i])));
    if (i > 0) out += ' ';
    out += tmp;
  }
  return out.empty() ? std::string("(empty file)") : out;
}

void check_dimensions(const fs::path& path, std::int64_t w, std::int64_t h) {
  if (w < kMinMapSide || h < kMinMapSide) {
    throw MapLoadError(MapErrorKind::TooSmall, path, 0,
                       "map is " + std::to_string(w) + "x" + std::to_string(h) +
                           " cells; at least " + std::to_string(kMinMapSide) + "x" +
                           std::to_string(kMinMapSide) + " are needed");
  }
  if (w > kMaxMapCells || h > kMaxMapCells || w * h > kMaxMapCells) {
    throw MapLoadError(MapErrorKind::TooLarge, path, 0,
                       "map is " + std::to_string(w) + "x" + std::to_string(h) +
                           " cells, above the limit of " + std::to_string(kMaxMapCells) +
                           " cells (2.5e8); refused before decoding");
  }
}

// Cursor over a PGM header: whitespace and '#' comments may appear between tokens.
struct PgmCursor {
  const fs::path& path;
  std::string_view b;
  std::size_t pos = 2;
  std::vector<std::string> comments;

  void skip_space_and_comments() {
    while (pos < b.size()) {
      const char c = b[pos];
      if (c == '#') {
        const std::size_t end = b.find('\n', pos);
        const std::size_t stop = end == std::string_view::npos ? b.size() : end;
        comments.emplace_back(b.substr(pos + 1, stop - pos - 1));
        pos = stop;
      } else if (std::isspace(static_cast<unsigned char>(c)) != 0) {
        ++pos;
      } else {
        break;
      }
    }
  }

  // Reads one unsigned decimal number; `what` names the field in messages.
  std::int64_t number(const char* what) {
    skip_space_and_comments();
    if (pos >= b.size()) {
      throw MapLoadError(MapErrorKind::Truncated, path, 0,
                         std::string("PGM header ends before the ") + what);
    }
    if (std::isdigit(static_cast<unsigned char>(b[pos])) == 0) {
      throw MapLoadError(MapErrorKind::BadHeader, path, 0,
                         std::string("PGM header: expected the ") + what + " at byte " +
                             std::to_string(pos) + ", found '" + std::string(1, b[pos]) + "'");
    }
    std::int64_t v = 0;
    while (pos < b.size() && std::isdigit(static_cast<unsigned char>(b[pos])) != 0) {
      v = v * 10 + (b[pos] - '0');
      if (v > (std::int64_t{1} << 40)) {
        throw MapLoadError(MapErrorKind::BadHeader, path, 0,
                           std::string("PGM header: ") + what + " is absurdly large");
      }
      ++pos;
    }
    return v;
  }
};

// Finds "<number> m/pix" (map_saver) or "resolution <number>" in the header comments.
std::optional<double> resolution_from_comments(const std::vector<std::string>& comments) {
  for (const auto& c : comments) {
    const std::size_t at = c.find("m/pix");
    if (at == std::string::npos) continue;
    std::size_t end = at;
    while (end > 0 && c[end - 1] == ' ') --end;
    std::size_t begin = end;
    while (begin > 0 && (std::isdigit(static_cast<unsigned char>(c[begin - 1])) != 0 ||
                         c[begin - 1] == '.')) {
      --begin;
    }
    if (begin == end) continue;
    try {
      const double v = std::stod(c.substr(begin, end - begin));
      if (v > 0.0) return v;
    } catch (const std::exception&) {
      continue;
    }
  }
  return std::nullopt;
}

ImageHeader parse_pgm_header(const fs::path& path, std::string_view b, std::size_t* data_start) {
  ImageHeader h;
  h.format = b[1] == '2' ? ImageFormat::PgmAscii : ImageFormat::PgmBinary;
  PgmCursor cur{path, b, 2, {}};
  h.width = cur.number("width");
  h.height = cur.number("height");
  const std::int64_t maxval = cur.number("maxval");
  if (maxval < 1 || maxval > 65535) {
    throw MapLoadError(MapErrorKind::BadHeader, path, 0,
                       "PGM maxval " + std::to_string(maxval) + " is outside 1..65535");
  }
  h.maxval = static_cast<int>(maxval);
  if (cur.pos >= b.size()) {
    if (h.width * h.height > 0) {
      throw MapLoadError(MapErrorKind::Truncated, path, 0, "PGM file ends right after its header");
    }
  } else if (std::isspace(static_cast<unsigned char>(b[cur.pos])) == 0) {
    throw MapLoadError(MapErrorKind::BadHeader, path, 0,
                       "PGM header: expected one whitespace byte after maxval");
  }
  *data_start = cur.pos + 1;
  h.comment_resolution = resolution_from_comments(cur.comments);
  return h;
}

std::uint8_t scale_to_8bit(std::int64_t v, int maxval) {
  if (maxval == 255) return static_cast<std::uint8_t>(v);
  return static_cast<std::uint8_t>((v * 255 + maxval / 2) / maxval);
}

cv::Mat1b decode_pgm(const fs::path& path, std::string_view b, const ImageHeader& h,
                     std::size_t start) {
  const int w = static_cast<int>(h.width), rows = static_cast<int>(h.height);
  const std::int64_t cells = h.width * h.height;
  cv::Mat1b out(rows, w);
  if (h.format == ImageFormat::PgmBinary) {
    const std::int64_t bpp = h.maxval > 255 ? 2 : 1;
    const std::int64_t need = cells * bpp;
    const std::int64_t have = start <= b.size() ? static_cast<std::int64_t>(b.size() - start) : 0;
    if (have < need) {
      throw MapLoadError(MapErrorKind::Truncated, path, 0,
                         "PGM (P5) pixel data is truncated: header says " + std::to_string(w) +
                             "x" + std::to_string(rows) + " = " + std::to_string(need) +
                             " bytes, file has " + std::to_string(have));
    }
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + start);
    for (int r = 0; r < rows; ++r) {
      std::uint8_t* o = out.ptr<std::uint8_t>(r);
      for (int c = 0; c < w; ++c, p += bpp) {
        const std::int64_t v = bpp == 2 ? (std::int64_t{p[0]} << 8) | p[1] : std::int64_t{p[0]};
        if (v > h.maxval) {
          throw MapLoadError(MapErrorKind::BadHeader, path, 0,
                             "PGM pixel (" + std::to_string(c) + "," + std::to_string(r) +
                                 ") = " + std::to_string(v) + " exceeds maxval " +
                                 std::to_string(h.maxval));
        }
        o[c] = scale_to_8bit(v, h.maxval);
      }
    }
    return out;
  }
  // P2: whitespace-separated decimal samples; comments are allowed by tolerant readers.
  PgmCursor cur{path, b, start > 0 ? start - 1 : 0, {}};
  for (std::int64_t i = 0; i < cells; ++i) {
    cur.skip_space_and_comments();
    if (cur.pos >= b.size()) {
      throw MapLoadError(MapErrorKind::Truncated, path, 0,
                         "PGM (P2) pixel data is truncated: header says " + std::to_string(cells) +
                             " samples, file has " + std::to_string(i));
    }
    const std::int64_t v = cur.number("pixel value");
    if (v > h.maxval) {
      throw MapLoadError(MapErrorKind::BadHeader, path, 0,
                         "PGM sample " + std::to_string(i) + " = " + std::to_string(v) +
                             " exceeds maxval " + std::to_string(h.maxval));
    }
    out(static_cast<int>(i / w), static_cast<int>(i % w)) = scale_to_8bit(v, h.maxval);
  }
  return out;
}

cv::Mat1b decode_png(const fs::path& path, std::string_view b, const ImageHeader& h) {
  const cv::Mat raw(1, static_cast<int>(b.size()), CV_8UC1,
                    const_cast<char*>(b.data()));  // imdecode only reads
  cv::Mat img = cv::imdecode(raw, cv::IMREAD_UNCHANGED);
  if (img.empty()) {
    throw MapLoadError(MapErrorKind::Truncated, path, 0,
                       "PNG data could not be decoded (truncated or corrupt file, " +
                           std::to_string(b.size()) + " bytes)");
  }
  if (img.cols != h.width || img.rows != h.height) {
    throw MapLoadError(MapErrorKind::BadHeader, path, 0, "decoded PNG size differs from its header");
  }
  if (img.depth() == CV_16U) {
    cv::Mat tmp;
    img.convertTo(tmp, CV_8U, 1.0 / 257.0);
    img = tmp;
  } else if (img.depth() != CV_8U) {
    throw MapLoadError(MapErrorKind::BadHeader, path, 0, "unsupported PNG sample depth");
  }
  const int ch = img.channels();
  // Colour channels are averaged like map_server does; the alpha channel (last of 2 or 4) is left
  // out of the average (map_server folds it in for trinary mode, which would turn opaque black
  // walls of grey+alpha PNGs into mid-grey "unknown").
  const int colour = (ch == 4 || ch == 2) ? ch - 1 : ch;
  cv::Mat1b out(img.rows, img.cols);
  for (int r = 0; r < img.rows; ++r) {
    const std::uint8_t* in = img.ptr<std::uint8_t>(r);
    std::uint8_t* o = out.ptr<std::uint8_t>(r);
    for (int c = 0; c < img.cols; ++c, in += ch) {
      int sum = 0;
      for (int k = 0; k < colour; ++k) sum += in[k];
      o[c] = static_cast<std::uint8_t>((sum + colour / 2) / colour);
    }
  }
  return out;
}

}  // namespace

ImageHeader read_image_header(const fs::path& path, std::string_view b) {
  ImageHeader h;
  if (is_png(b)) {
    if (b.size() < 24 || b.substr(12, 4) != "IHDR") {
      throw MapLoadError(b.size() < 24 ? MapErrorKind::Truncated : MapErrorKind::BadHeader, path, 0,
                         "PNG file has no complete IHDR header");
    }
    h.format = ImageFormat::Png;
    h.width = be32(b, 16);
    h.height = be32(b, 20);
  } else if (b.size() >= 2 && b[0] == 'P' && (b[1] == '2' || b[1] == '5')) {
    std::size_t start = 0;
    h = parse_pgm_header(path, b, &start);
  } else if (b.size() >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7') {
    throw MapLoadError(MapErrorKind::NotAnImage, path, 0,
                       std::string("netpbm type P") + b[1] +
                           " is not supported; maps must be greyscale PGM (P2/P5) or PNG");
  } else {
    throw MapLoadError(MapErrorKind::NotAnImage, path, 0,
                       "not a PNG or PGM image (first bytes: " + describe_first_bytes(b) + ")");
  }
  check_dimensions(path, h.width, h.height);
  return h;
}

GreyImage read_grey_image(const fs::path& path) {
  // The header is checked on the first 1 MiB, so a map above the size limit is refused before
  // the file is read in full or any pixel buffer is allocated.
  constexpr std::size_t kPrefix = std::size_t{1} << 20;
  const std::string prefix = read_bytes(path, kPrefix);
  GreyImage out;
  bool header_done = false;
  try {
    out.header = read_image_header(path, prefix);
    header_done = true;
  } catch (const MapLoadError& e) {
    // A header that does not fit in the prefix (megabytes of PGM comments) is re-read in full.
    if (e.kind() != MapErrorKind::Truncated || prefix.size() < kPrefix) throw;
  }
  const std::string bytes = prefix.size() < kPrefix ? prefix : read_file_bytes(path);
  if (!header_done) out.header = read_image_header(path, bytes);
  if (out.header.format == ImageFormat::Png) {
    out.grey = decode_png(path, bytes, out.header);
  } else {
    std::size_t start = 0;
    parse_pgm_header(path, bytes, &start);
    out.grey = decode_pgm(path, bytes, out.header, start);
  }
  return out;
}

}  // namespace ksmc::stdlib::indoor::io
