// labels.png (16-bit unit id per cell) and overlay.png (seed Fig. 3.21-d / 3.32-d style: the
// classified map in greys, units filled with their type's colour (legend in a band below
// the map when the run has types), unit walls
// blue, doors cyan, topology lines centre - door - centre, type letter + id at each unit centre,
// the --path route in magenta from a green start to a red goal).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

// Unit id per cell (0 = none), rows x cols of the map; units are filled in the given order, so a
// later unit wins where two overlap. A cell is covered when its centre is inside the rectangle.
cv::Mat1w render_labels(const WorldResult& w, int rows, int cols);

// Integer upscale factor of the overlay: small maps are enlarged (to about 1200 px on the long
// side, at most 32x) so the id text is legible; maps of 1200 px or more stay at 1x.
int overlay_scale(int rows, int cols);

// BGR overlay image of `grid` (Cell values) upscaled by overlay_scale(); with types, the legend
// band adds rows below the map.
cv::Mat3b render_overlay(const ClassGrid& grid, const WorldResult& w);

// PNG bytes (cv::imencode, fixed parameters, so identical input gives identical bytes).
std::vector<unsigned char> encode_png(const cv::Mat& image, const std::string& what);

void write_labels_png(const std::filesystem::path& path, const WorldResult& w, int rows, int cols);
void write_overlay_png(const std::filesystem::path& path, const ClassGrid& grid, const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
