// graph.dot (seed Fig. 3.32-e): the topology graph for Graphviz. One node per unit labelled with
// its type letter and id (R12; the letter from the run's own type list, io/type_style.h) and
// filled with its type's colour; solid door edges labelled with the door id, dashed adjacency
// edges (units whose walls touch, no door needed). A door to unit 0 goes to an "outside" node.
// graph.png is graph.dot rendered by Graphviz `dot` when it is on PATH.
#pragma once

#include <filesystem>
#include <string>

#include "stdlib/indoor/io/world_result.h"

namespace ksmc::stdlib::indoor::io {

std::string graph_dot_text(const WorldResult& w);
void write_graph_dot(const std::filesystem::path& path, const WorldResult& w);

}  // namespace ksmc::stdlib::indoor::io
