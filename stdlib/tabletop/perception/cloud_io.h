// Point clouds in and out: PLY / PCD with own readers (not PCL's, which trust the header:
// a huge count or a truncated body aborts or allocates gigabytes), a unit scale to metres
// and validation that names the file and the place (header line, body line, byte offset,
// point).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace ksmc::stdlib::tabletop::perception {

// Every front-end failure: the message starts with the input file's name.
class CloudError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using Points = std::vector<Eigen::Vector3d>;

enum class Units { m, cm, mm };

// "m" | "cm" | "mm"; throws std::invalid_argument naming the accepted values.
Units parse_units(std::string_view text);
double metres_per_unit(Units units);

// Reads `path` and scales it to metres: PLY (ascii, binary_little_endian / big_endian;
// x, y, z of the first `vertex` element, any numeric type; other properties and elements,
// lists included, read past) or PCD v0.5-0.7 (DATA ascii, binary, binary_compressed; fields
// x, y, z of any numeric type). Throws CloudError "<file>: ..." when the file is
// unreadable or corrupt (a count or size the bytes cannot hold, a missing x / y / z, a
// non-number), has no points, or holds a NaN / infinite coordinate (the message gives the
// index of the first bad point). Missing returns are left out and counted in
// `*missing_returns` when given: points at exactly (0, 0, 0) (a depth sensor's own centre is
// never a surface it sees) and, in an organised PCD (HEIGHT > 1), points NaN in all of x,
// y and z (PCL's convention). A cloud of nothing else has no points.
Points load_cloud(const std::filesystem::path& path, Units units = Units::m, std::size_t* missing_returns = nullptr);

// Deterministic ASCII PLY (x y z, metres, 6 decimals), written atomically.
void save_ply(const std::filesystem::path& path, const Points& points);
std::string ply_text(const Points& points);

}  // namespace ksmc::stdlib::tabletop::perception
