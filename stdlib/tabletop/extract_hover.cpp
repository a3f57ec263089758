#include "stdlib/tabletop/extract_hover.h"

namespace ksmc::stdlib::tabletop {

bool extract_hover(std::size_t index, const std::vector<std::vector<char>>& contact,
                   const std::vector<std::vector<char>>& intersect) {
  for (std::size_t j = 0; j < contact.size(); ++j) {
    if (j == index) continue;
    if (contact[index][j] || intersect[index][j]) return false;
  }
  return true;
}

}  // namespace ksmc::stdlib::tabletop
