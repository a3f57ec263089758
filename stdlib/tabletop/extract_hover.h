// hover(o): o has no contact and no intersection with any other body, the table
// included (seed §4.5.5).
#pragma once

#include <cstddef>
#include <vector>

namespace ksmc::stdlib::tabletop {

// `contact` and `intersect` are square, symmetric relation matrices over all bodies
// (the table included); returns hover for body `index`.
bool extract_hover(std::size_t index, const std::vector<std::vector<char>>& contact,
                   const std::vector<std::vector<char>>& intersect);

}  // namespace ksmc::stdlib::tabletop
