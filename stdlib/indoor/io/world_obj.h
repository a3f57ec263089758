// world.obj (seed Fig. 3.38): the world's walls as a Wavefront OBJ mesh in map-frame metres
// (x, y as in map_frame.h, z up, floor at z = 0). Every unit edge becomes a box as thick as the
// wall band the model predicts inside the unit (WorldResult::wall_thickness cells, inside the
// edge) and `height` metres high; a door whose segment lies on the edge (both end points
// within two wall thicknesses of its line) cuts the box, leaving a floor-to-top gap. Each box
// is its own group ("g u<id>_wall<k>"), with 8 vertices and 6 outward-facing quads.
#pragma once

#include <filesystem>
#include <string>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

inline constexpr double kWallHeight = 2.5;  // m

std::string world_obj_text(const WorldResult& w, double height = kWallHeight);
void write_world_obj(const std::filesystem::path& path, const WorldResult& w, double height = kWallHeight);

}  // namespace ksmc::stdlib::indoor::io
