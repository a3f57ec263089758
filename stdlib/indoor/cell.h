// Cell classes of an occupancy grid (seed eq. 3.7) and of the predicted map C_W (eq. 3.8).
// Shared vocabulary of the indoor stdlib: map loading, world rasterisation, likelihood, detectors.
#pragma once

#include <cstdint>

#include <opencv2/core/mat.hpp>

namespace ksmc::stdlib::indoor {

// Observed map class per cell: index into the rows of the likelihood lookup table (Table 3.1).
enum class Cell : std::uint8_t { Free = 0, Unknown = 1, Occupied = 2 };

// Predicted class per cell from the world W: index into the columns of the lookup table.
enum class Predicted : std::uint8_t { Free = 0, Unknown = 1, Wall = 2 };

// A classified map: one Cell value per pixel, row-major, image convention (row 0 at the top).
using ClassGrid = cv::Mat1b;

}  // namespace ksmc::stdlib::indoor
