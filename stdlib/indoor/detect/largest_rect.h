// The largest axis-aligned rectangle of non-zero cells in a binary mask (the classic
// histogram-and-stack scan, O(rows x cols)). The FSU detector proposes it for a free-space
// component that fills its bounding box poorly (a ring of corridors round a courtyard, an
// L-shaped wing), so that the component can be covered piece by piece.
#pragma once

#include <opencv2/core/mat.hpp>
#include <opencv2/core/types.hpp>

namespace ksmc::stdlib::indoor::detect {

// Among the rectangles of largest area, the first the scan meets (rows top to bottom, by the
// rectangle's bottom row): the same mask, the same rectangle. An empty cv::Rect when no cell
// is set.
cv::Rect largest_rectangle(const cv::Mat1b& mask);

}  // namespace ksmc::stdlib::indoor::detect
