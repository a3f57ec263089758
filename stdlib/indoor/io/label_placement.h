// Where overlay.png puts the unit labels (type letter and id, e.g. R12): at each unit's centre,
// unless that box would overlap a label placed before it (two units with nearby centres: a
// small room inside a big one, two halves of a split). Then the label moves up or down by
// whole label heights, nearest first (down before up), until it overlaps none; after
// kMaxLabelSteps steps each way it stays at the centre. Labels are placed in the order given,
// so the result is deterministic.
#pragma once

#include <vector>

#include <opencv2/core/types.hpp>

namespace ksmc::stdlib::indoor::io {

inline constexpr int kMaxLabelSteps = 4;

// The centre of each label's box: `wanted[i]` or a vertical shift of it. `sizes[i]` is the
// box of label i (its text plus halo); `pad` pixels are kept free between two boxes.
std::vector<cv::Point> place_labels(const std::vector<cv::Point>& wanted, const std::vector<cv::Size>& sizes, int pad);

}  // namespace ksmc::stdlib::indoor::io
