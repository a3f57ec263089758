// A strip of a box's face seen as a box of its own: the clustering cut off a few rows of a
// side face (seen at a grazing angle, or past a shadow) and the box fit made them a thin box
// (one face seen gives no thickness). A thin box whose points lie on a larger box's surface is
// part of that box, not an object. Points deep inside a box are no strip of it: a surface the
// sensor cannot have seen there (a multipath ghost behind a glossy face) stays a box of its
// own, for the inference to call false.
#pragma once

#include "stdlib/tabletop/perception/box_fit.h"

namespace ksmc::stdlib::tabletop::perception {

struct FaceStripOptions {
  double thin = 0.012;    // m; a box with an extent this small was seen by one face
  double share = 0.9;     // ... and is a strip of `outer` when this share of its points ...
  double margin = 0.01;   // ... lie within this (m) of `outer`'s surface
};

// Whether `box` has an extent under options.thin: one face of it was seen.
inline bool is_thin(const UprightBox& box, const FaceStripOptions& options = {}) {
  return box.size.minCoeff() <= options.thin;
}

// Whether `box` (its points `own`) is a strip of `outer`'s faces: `box` is thin, `outer` has
// the larger volume, and options.share of `own` lie within options.margin of `outer`'s surface.
bool is_face_strip(const UprightBox& box, const Points& own, const UprightBox& outer,
                   const FaceStripOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
