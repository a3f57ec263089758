// How the unit types look in the pictures and the graph: one colour and one short letter per
// type, both taken from the run's own type list (WorldResult::types, the domain's exactly-one-of
// group over units, in declaration order), never from fixed type names.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ksmc::stdlib::indoor::io {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

// The colour of `type` by its place in `types` (the seed's figures: yellow, green, blue, grey,
// then red, purple, orange, teal, repeating); light grey for "" or a type not in the list.
Rgb type_colour(const std::vector<std::string>& types, const std::string& type);

// `c` blended towards white by `amount` in [0, 1] (graph node fills).
Rgb lighten(Rgb c, double amount);

// "#rrggbb".
std::string hex(Rgb c);

// The type's letter: its first character upper-cased (Room -> R, Corr -> C, Hall -> H,
// Other -> O). When several types of the list share it, the shortest prefix that tells them
// apart (first character upper-cased). "" for "" or a type not in the list.
std::string type_letter(const std::vector<std::string>& types, const std::string& type);

}  // namespace ksmc::stdlib::indoor::io
