// Overlay image: each object's OBB projected into the camera image, false estimates
// red, objects on a hidden object cyan, undecided ones yellow, the others green, with id
// labels. The
// background is the scene's image when it loads, else a blank canvas.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "stdlib/tabletop/result.h"

namespace ksmc::stdlib::tabletop {

// `warnings` receives a note when the scene names an image that cannot be read.
cv::Mat render_overlay(const TabletopResult& result, std::vector<std::string>& warnings);

}  // namespace ksmc::stdlib::tabletop
