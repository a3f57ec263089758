#include "stdlib/indoor/detect/largest_rect.h"

#include <vector>

namespace ksmc::stdlib::indoor::detect {

cv::Rect largest_rectangle(const cv::Mat1b& mask) {
  cv::Rect best;
  long best_area = 0;
  std::vector<int> height(static_cast<std::size_t>(mask.cols) + 1, 0);  // sentinel column of 0
  std::vector<int> stack;
  stack.reserve(height.size());
  for (int r = 0; r < mask.rows; ++r) {
    const unsigned char* row = mask.ptr<unsigned char>(r);
    for (int c = 0; c < mask.cols; ++c) height[static_cast<std::size_t>(c)] = row[c] != 0 ? height[static_cast<std::size_t>(c)] + 1 : 0;
    stack.clear();
    for (int c = 0; c <= mask.cols; ++c) {
      const int h = height[static_cast<std::size_t>(c)];
      while (!stack.empty() && height[static_cast<std::size_t>(stack.back())] >= h) {
        const int top = height[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        const int left = stack.empty() ? 0 : stack.back() + 1;
        const long area = static_cast<long>(top) * (c - left);
        if (area > best_area) {
          best_area = area;
          best = cv::Rect(left, r - top + 1, c - left, top);
        }
      }
      stack.push_back(c);
    }
  }
  return best;
}

}  // namespace ksmc::stdlib::indoor::detect
