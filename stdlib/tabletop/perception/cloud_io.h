// Point clouds in and out: PLY / PCD through PCL, with a unit scale to metres and
// validation (empty cloud, NaN / infinite coordinates) that names the file.
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

// Reads `path` (.ply or .pcd, ASCII or binary) and scales it to metres. Throws CloudError
// "<file>: ..." when the file is unreadable, has no points, or holds a NaN / infinite
// coordinate (the message gives the index of the first bad point).
Points load_cloud(const std::filesystem::path& path, Units units = Units::m);

// Deterministic ASCII PLY (x y z, metres, 6 decimals), written atomically.
void save_ply(const std::filesystem::path& path, const Points& points);
std::string ply_text(const Points& points);

}  // namespace ksmc::stdlib::tabletop::perception
