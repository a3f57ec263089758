#include "stdlib/indoor/io/doorway_spaces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr double kMinSpace = 1.0;  // m^2: a space, not a corner the unit missed
constexpr double kDoorway = 1.2;   // m of contact: a door and its frame

constexpr int kDr[4] = {-1, 0, 0, 1}, kDc[4] = {0, -1, 1, 0};

int find(std::vector<int>& parent, int x) {
  while (parent[static_cast<std::size_t>(x)] != x) {
    parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    x = parent[static_cast<std::size_t>(x)];
  }
  return x;
}

}  // namespace

void detach_spaces_behind_doorways(const ClassGrid& grid, double resolution, const cv::Mat1b& explained, cv::Mat1w& label) {
  const double res = resolution > 0.0 ? resolution : 0.05;
  const auto filled = [&](int r, int c) { return label(r, c) != 0 && explained(r, c) == 0; };
  const auto inside = [&](int r, int c) { return r >= 0 && c >= 0 && r < grid.rows && c < grid.cols; };
  // Components of filled cells of one label.
  cv::Mat1i comp(grid.rows, grid.cols, -1);
  std::vector<long> area, contact;
  std::vector<std::pair<int, int>> stack;
  int max_id = 0;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      max_id = std::max<int>(max_id, label(r, c));
      if (!filled(r, c) || comp(r, c) >= 0) continue;
      const int k = static_cast<int>(area.size());
      area.push_back(0);
      contact.push_back(0);
      comp(r, c) = k;
      stack.assign(1, {r, c});
      while (!stack.empty()) {
        const auto [pr, pc] = stack.back();
        stack.pop_back();
        ++area.back();
        bool touches = false;
        for (int d = 0; d < 4; ++d) {
          const int nr = pr + kDr[d], nc = pc + kDc[d];
          if (!inside(nr, nc) || label(nr, nc) != label(r, c)) continue;
          if (explained(nr, nc) != 0) touches = true;
          else if (comp(nr, nc) < 0) {
            comp(nr, nc) = k;
            stack.emplace_back(nr, nc);
          }
        }
        if (touches) ++contact.back();
      }
    }
  const auto min_cells = static_cast<long>(std::ceil(kMinSpace / (res * res)));
  const auto max_contact = static_cast<long>(std::lround(kDoorway / res));
  std::vector<char> detached(area.size(), 0);
  for (std::size_t k = 0; k < area.size(); ++k) detached[k] = area[k] >= min_cells && contact[k] > 0 && contact[k] <= max_contact;
  // Detached components that touch are one space.
  std::vector<int> parent(area.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const int a = comp(r, c);
      if (a < 0 || !detached[static_cast<std::size_t>(a)]) continue;
      for (int d = 2; d < 4; ++d) {  // right and down: every touching pair once
        const int nr = r + kDr[d], nc = c + kDc[d];
        if (!inside(nr, nc)) continue;
        const int b = comp(nr, nc);
        if (b < 0 || b == a || !detached[static_cast<std::size_t>(b)]) continue;
        const int ra = find(parent, a), rb = find(parent, b);
        if (ra != rb) parent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
      }
    }
  std::vector<int> id(area.size(), 0);
  int next = max_id;
  for (std::size_t k = 0; k < area.size(); ++k) {  // components in scan order: ids are deterministic
    if (!detached[k]) continue;
    const auto root = static_cast<std::size_t>(find(parent, static_cast<int>(k)));
    if (id[root] == 0 && next < 0xffff) id[root] = ++next;
    id[k] = id[root];
  }
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (const int k = comp(r, c); k >= 0 && id[static_cast<std::size_t>(k)] != 0)
        label(r, c) = static_cast<std::uint16_t>(id[static_cast<std::size_t>(k)]);
}

}  // namespace ksmc::stdlib::indoor::io
