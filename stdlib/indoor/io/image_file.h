// Reading a map image (PNG or PGM P2/P5) into 8-bit grey values, with the size checked from the
// header before any pixel buffer is allocated. The PGM parser is our own so that truncation,
// bad headers and the map_saver resolution comment are reported precisely.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <opencv2/core/mat.hpp>

namespace ksmc::stdlib::indoor::io {

enum class ImageFormat { Png, PgmAscii, PgmBinary };

struct ImageHeader {
  ImageFormat format = ImageFormat::Png;
  std::int64_t width = 0;
  std::int64_t height = 0;
  int maxval = 255;                              // PGM only
  std::optional<double> comment_resolution;      // PGM "# ... 0.050 m/pix" written by map_saver
};

struct GreyImage {
  ImageHeader header;
  cv::Mat1b grey;  // channel average (alpha excluded), 16-bit samples scaled to 8 bits
};

// Parses only the header of `bytes` (the content of `path`, used for messages).
// Throws MapLoadError (NotAnImage, BadHeader, Truncated, TooSmall, TooLarge).
ImageHeader read_image_header(const std::filesystem::path& path, std::string_view bytes);

// Reads and decodes the whole file. Throws MapLoadError (Unreadable plus the header errors).
GreyImage read_grey_image(const std::filesystem::path& path);

// Reads a whole file into memory; throws MapLoadError(Unreadable) naming the path and the reason.
std::string read_file_bytes(const std::filesystem::path& path);

}  // namespace ksmc::stdlib::indoor::io
