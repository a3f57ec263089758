#include "stdlib/indoor/io/wall_gap_cuts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <vector>

#include "stdlib/indoor/cell.h"

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr double kMaxGap = 3.0;            // m: an open office front (a door is up to 1.2 m)
constexpr double kWallRun = 0.3;           // m of wall beyond each end, along the gap's line
constexpr double kMaxWallThickness = 0.4;  // m across the line: a wall, not a block
constexpr double kMinPiece = 1.0;          // m^2: a piece that is a space of its own

struct Cuts {
  const ClassGrid& grid;
  const cv::Mat1w& label;
  int run, thick, max_gap;
  cv::Mat1b cut;

  bool occupied(int r, int c) const {
    return r >= 0 && c >= 0 && r < grid.rows && c < grid.cols && grid(r, c) == static_cast<std::uint8_t>(Cell::Occupied);
  }
  // A wall continues from (r, c) for `run` cells in direction (dr, dc), and at its far end it
  // is at most `thick` cells thick across that direction.
  bool wall_along(int r, int c, int dr, int dc) const {
    for (int k = 0; k < run; ++k)
      if (!occupied(r + dr * k, c + dc * k)) return false;
    const int fr = r + dr * (run - 1), fc = c + dc * (run - 1);
    int n = 1;
    for (int s = 1; occupied(fr + dc * s, fc + dr * s) && n <= thick; ++s) ++n;
    for (int s = 1; occupied(fr - dc * s, fc - dr * s) && n <= thick; ++s) ++n;
    return n <= thick;
  }
  // Scan lines of direction (dr, dc): rows for (0, 1), columns for (1, 0).
  void scan(int dr, int dc) {
    const int lines = dc != 0 ? grid.rows : grid.cols, len = dc != 0 ? grid.cols : grid.rows;
    for (int l = 0; l < lines; ++l) {
      const auto at = [&](int k) { return dc != 0 ? std::pair{l, k} : std::pair{k, l}; };
      int i = 0;
      while (i < len) {
        const auto [r, c] = at(i);
        if (grid(r, c) != static_cast<std::uint8_t>(Cell::Free) || label(r, c) == 0) {
          ++i;
          continue;
        }
        int j = i;
        bool labelled = true;
        while (j < len) {
          const auto [rj, cj] = at(j);
          if (grid(rj, cj) != static_cast<std::uint8_t>(Cell::Free)) break;
          labelled = labelled && label(rj, cj) != 0;
          ++j;
        }
        // The free run [i, j) and the cells at its two ends.
        const auto [r0, c0] = at(i - 1 < 0 ? 0 : i - 1);
        const auto [r1, c1] = at(j < len ? j : len - 1);
        if (labelled && i > 0 && j < len && j - i <= max_gap && wall_along(r0, c0, -dr, -dc) && wall_along(r1, c1, dr, dc))
          for (int k = i; k < j; ++k) {
            const auto [rk, ck] = at(k);
            cut(rk, ck) = 1;
          }
        i = j;
      }
    }
  }
};

}  // namespace

void split_at_wall_gaps(const ClassGrid& grid, double resolution, cv::Mat1w& label) {
  const double res = resolution > 0.0 ? resolution : 0.05;
  Cuts cuts{grid, label, std::max(1, static_cast<int>(std::lround(kWallRun / res))),
            std::max(1, static_cast<int>(std::lround(kMaxWallThickness / res))),
            static_cast<int>(std::lround(kMaxGap / res)), cv::Mat1b(grid.rows, grid.cols, static_cast<std::uint8_t>(0))};
  cuts.scan(0, 1);
  cuts.scan(1, 0);
  // 4-connected pieces of each segment without its cut cells.
  cv::Mat1i piece(label.rows, label.cols, -1);
  std::vector<long> area;
  std::vector<int> owner;
  constexpr int kDr[4] = {-1, 0, 0, 1}, kDc[4] = {0, -1, 1, 0};
  std::vector<std::pair<int, int>> stack;
  int max_id = 0;
  for (int r = 0; r < label.rows; ++r)
    for (int c = 0; c < label.cols; ++c) {
      max_id = std::max<int>(max_id, label(r, c));
      if (label(r, c) == 0 || cuts.cut(r, c) || piece(r, c) >= 0) continue;
      const int p = static_cast<int>(area.size());
      area.push_back(0);
      owner.push_back(label(r, c));
      stack.assign(1, {r, c});
      piece(r, c) = p;
      while (!stack.empty()) {
        const auto [pr, pc] = stack.back();
        stack.pop_back();
        ++area.back();
        for (int k = 0; k < 4; ++k) {
          const int nr = pr + kDr[k], nc = pc + kDc[k];
          if (nr < 0 || nc < 0 || nr >= label.rows || nc >= label.cols) continue;
          if (label(nr, nc) != label(r, c) || cuts.cut(nr, nc) || piece(nr, nc) >= 0) continue;
          piece(nr, nc) = p;
          stack.emplace_back(nr, nc);
        }
      }
    }
  const auto min_cells = static_cast<long>(std::ceil(kMinPiece / (res * res)));
  std::map<int, std::vector<int>> large;  // segment id -> its large pieces, in scan order
  for (std::size_t p = 0; p < area.size(); ++p)
    if (area[p] >= min_cells) large[owner[p]].push_back(static_cast<int>(p));
  std::vector<int> target(area.size(), 0);
  std::vector<char> split_segment(static_cast<std::size_t>(max_id) + 1, 0);
  int next = max_id;
  for (auto& [id, ps] : large) {
    if (ps.size() < 2) continue;
    split_segment[static_cast<std::size_t>(id)] = 1;
    const auto biggest = *std::max_element(ps.begin(), ps.end(), [&](int a, int b) { return area[a] < area[b]; });
    for (const int p : ps) target[static_cast<std::size_t>(p)] = p == biggest ? id : (next < 0xffff ? ++next : id);
  }
  // Cut cells and small pieces of a split segment: the nearest large piece through its cells.
  cv::Mat1w out = label.clone();
  cv::Mat1b done(label.rows, label.cols, static_cast<std::uint8_t>(0));
  std::deque<std::pair<int, int>> queue;
  for (int r = 0; r < label.rows; ++r)
    for (int c = 0; c < label.cols; ++c) {
      if (label(r, c) == 0 || !split_segment[label(r, c)]) continue;
      const int p = piece(r, c);
      if (p >= 0 && target[static_cast<std::size_t>(p)] != 0) {
        out(r, c) = static_cast<std::uint16_t>(target[static_cast<std::size_t>(p)]);
        done(r, c) = 1;
        queue.emplace_back(r, c);
      }
    }
  while (!queue.empty()) {
    const auto [r, c] = queue.front();
    queue.pop_front();
    for (int k = 0; k < 4; ++k) {
      const int nr = r + kDr[k], nc = c + kDc[k];
      if (nr < 0 || nc < 0 || nr >= label.rows || nc >= label.cols) continue;
      if (done(nr, nc) || label(nr, nc) != label(r, c)) continue;
      out(nr, nc) = out(r, c);
      done(nr, nc) = 1;
      queue.emplace_back(nr, nc);
    }
  }
  label = out;
}

}  // namespace ksmc::stdlib::indoor::io
