// scene.dot: the scene graph for Graphviz — units as nodes labelled with id and type, adjacency
// edges (thin, grey) and door edges (bold, labelled with the door id). A door to unit 0 goes to an
// "outside" node.
#pragma once

#include <filesystem>
#include <string>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

std::string scene_dot_text(const WorldResult& w);
void write_scene_dot(const std::filesystem::path& path, const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
