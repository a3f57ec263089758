#include "stdlib/indoor/io/wall_gap_cuts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "stdlib/indoor/cell.h"
#include "stdlib/indoor/io/corridor_shape.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/detect/orientation.h"
#include "stdlib/indoor/io/thin_walls.h"

namespace ksmc::stdlib::indoor::io {

namespace {

constexpr double kMaxGap = 3.0;            // m: an open office front (a door is up to 1.2 m)
constexpr double kWallRun = 0.3;           // m of wall beyond each end, along the gap's line
constexpr double kMinPiece = 1.0;          // m^2: a piece that is a space of its own
constexpr double kMinWallPiece = 1.0;      // m: the longer side of the bounding box of a wall end's occupied blob
constexpr double kAlignedAngle = 1.0 * CV_PI / 180.0;  // rad: walls within 1 degree of the rows and columns are scanned along them
constexpr double kNearDirection = 3.0;  // degrees: units this close to the main direction share it
constexpr double kMinShare = 0.85;      // of the units' area in the main direction: the building has one frame
constexpr double kCorridorSpan = 0.75;     // of a corridor-shaped unit's width: a cut across it spans at least this,
constexpr double kSideSlack = 0.15;        // m: and reaches this close to each of its sides (a door frame narrows it more)
constexpr double kMaxCrossCut = 0.5;       // m along the corridor: a cut line, not a band
constexpr double kMaxEndGap = 1.4;         // m from a thin wall's end to the wall it points at: a door (1.2 m) and the Hough end's slack, under a corridor's width

struct Cuts {
  const ClassGrid& grid;
  const cv::Mat1w& label;
  int run, thick, max_gap;
  cv::Mat1b cut;
  // Per cell, whether its occupied 8-connected blob spans at least kMinWallPiece: part of a wall,
  // not a chair or a table leg (a row of them round a table is no wall line with gaps).
  cv::Mat1b wall_piece;

  bool occupied(int r, int c) const {
    return r >= 0 && c >= 0 && r < grid.rows && c < grid.cols && grid(r, c) == static_cast<std::uint8_t>(Cell::Occupied);
  }
  // How many cells at the far end of a wall's run must be thin across: 1 on the map's own grid.
  // On a grid turned by nearest neighbour a wall's faces are jagged by a cell, so that a wall
  // about as thick as `run`, crossing the scan line, ends in a cell standing out of its face on
  // some rows: there the last two cells must be thin (a wall lying along the line is thin all along).
  int thin_ends = 1;
  // A wall continues from (r, c) for `run` cells in direction (dr, dc), and at its far end (its
  // last thin_ends cells) it is at most `thick` cells thick across that direction.
  bool wall_along(int r, int c, int dr, int dc) const {
    for (int k = 0; k < run; ++k)
      if (!occupied(r + dr * k, c + dc * k)) return false;
    const auto thin_at = [&](int k) {
      const int fr = r + dr * k, fc = c + dc * k;
      int n = 1;
      for (int s = 1; occupied(fr + dc * s, fc + dr * s) && n <= thick; ++s) ++n;
      for (int s = 1; occupied(fr - dc * s, fc - dr * s) && n <= thick; ++s) ++n;
      return n <= thick;
    };
    for (int k = run - 1; k >= std::max(0, run - thin_ends); --k)
      if (!thin_at(k)) return false;
    return true;
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
        if (labelled && i > 0 && j < len && j - i <= max_gap && wall_piece(r0, c0) && wall_piece(r1, c1) &&
            wall_along(r0, c0, -dr, -dc) && wall_along(r1, c1, dr, dc))
          for (int k = i; k < j; ++k) {
            const auto [rk, ck] = at(k);
            cut(rk, ck) = 1;
          }
        i = j;
      }
    }
  }

  // The cell under point p of a line (cell centres at whole coordinates), or {-1, -1} outside.
  std::pair<int, int> cell_at(Point2 p) const {
    const int r = static_cast<int>(std::lround(p.y)), c = static_cast<int>(std::lround(p.x));
    if (r < 0 || c < 0 || r >= grid.rows || c >= grid.cols) return {-1, -1};
    return {r, c};
  }
  // Marks the free cells of `line` between t0 and t1 (t0 < t1) as cut, when every cell on the way
  // is a free, labelled cell; occupied cells only within 2 cells of either end (the wall ends
  // themselves): a gap that holds another wall (a corridor between two partitions) is no cut.
  void cut_between(const WallLine& line, double t0, double t1) {
    std::vector<std::pair<int, int>> cells;
    for (double t = t0; t <= t1; t += 0.5) {
      const auto [r, c] = cell_at(line.at(t));
      if (r < 0) return;
      if (occupied(r, c)) {
        if (t - t0 > 2.0 && t1 - t > 2.0) return;
        continue;
      }
      if (grid(r, c) != static_cast<std::uint8_t>(Cell::Free) || label(r, c) == 0) return;
      cells.emplace_back(r, c);
    }
    for (const auto& [r, c] : cells) cut(r, c) = 1;
  }
  // Whether the wall line ends in a junction at t (its end, facing `sign`): a wall across the
  // line, beyond the line's own half thickness (measured `back` cells before the end), from 2
  // cells before t through the wall's last occupied cells. A partition meeting a corridor wall
  // ends in a junction; one that ends at a doorway does not.
  bool junction(const WallLine& line, double t, int sign, double back) const {
    const Point2 n{-line.dir.y, line.dir.x};
    double half = 1.0;
    const Point2 q = line.at(t - sign * back);
    for (const int side : {-1, 1})
      for (int k = 1; k <= 10; ++k) {
        const auto [r, c] = cell_at({q.x + side * k * n.x, q.y + side * k * n.y});
        if (r < 0 || !occupied(r, c)) break;
        half = std::max(half, static_cast<double>(k));
      }
    const auto across = [&](Point2 p) {
      const auto [r1, c1] = cell_at({p.x + (half + 2.0) * n.x, p.y + (half + 2.0) * n.y});
      const auto [r2, c2] = cell_at({p.x - (half + 2.0) * n.x, p.y - (half + 2.0) * n.y});
      return r1 >= 0 && r2 >= 0 && occupied(r1, c1) && occupied(r2, c2);
    };
    for (double s = t - 2.0 * sign; sign * (t - s) > 0.0; s += 0.5 * sign)
      if (across(line.at(s))) return true;
    for (double s = t; std::abs(s - t) < 4.0; s += 0.5 * sign) {
      const Point2 p = line.at(s);
      const auto [r, c] = cell_at(p);
      if (r < 0 || !occupied(r, c)) break;
      if (across(p)) return true;
    }
    return false;
  }
  // From the free end t of a thin wall line, in direction `sign`: past the wall's last occupied
  // cells, a run of free, labelled cells of at most `max_free` that ends at an occupied cell is
  // a doorway between this wall's end and the wall it points at.
  void cut_beyond(const WallLine& line, double t, int sign, double max_free) {
    double s = t;
    for (int k = 0; k < 8; ++k, s += 0.5 * sign) {  // the wall's own end cells
      const auto [r, c] = cell_at(line.at(s));
      if (r < 0) return;
      if (!occupied(r, c)) break;
    }
    const double start = s;
    for (; std::abs(s - start) <= max_free; s += 0.5 * sign) {
      const auto [r, c] = cell_at(line.at(s));
      if (r < 0) return;
      if (occupied(r, c)) {
        if (std::abs(s - start) >= 1.0) cut_between(line, std::min(start, s), std::max(start, s));
        return;
      }
      if (grid(r, c) != static_cast<std::uint8_t>(Cell::Free) || label(r, c) == 0) return;
    }
  }
  // Thin wall lines: the gaps between the pieces of one line (up to max_gap) and the doorway
  // beyond each of its two ends (up to max_end cells) are cuts, where the wall ends free (not in
  // a junction). `metre`: cells per metre.
  void cut_lines(const std::vector<WallLine>& lines, double max_end, double metre) {
    for (const WallLine& line : lines) {
      const auto& iv = line.covered;
      // The wall's thickness is measured 0.5 m back from an end (less on a short line).
      const double back = std::min(0.5 * metre, 0.5 * (iv.back().second - iv.front().first));
      const auto free_end = [&](double t, int sign) { return !junction(line, t, sign, back); };
      for (std::size_t k = 1; k < iv.size(); ++k)
        if (iv[k].first - iv[k - 1].second <= max_gap && free_end(iv[k - 1].second, +1) && free_end(iv[k].first, -1))
          cut_between(line, iv[k - 1].second, iv[k].first);
      if (free_end(iv.front().first, -1)) cut_beyond(line, iv.front().first, -1, max_end);
      if (free_end(iv.back().second, +1)) cut_beyond(line, iv.back().second, +1, max_end);
    }
  }
};

// 255 where an occupied cell's 8-connected blob has a bounding box at least `min_cells` long.
cv::Mat1b wall_pieces(const ClassGrid& grid, double min_cells) {
  const cv::Mat1b occ = grid == static_cast<std::uint8_t>(Cell::Occupied);
  cv::Mat1i ids, stats;
  cv::Mat centroids;
  const int n = cv::connectedComponentsWithStats(occ, ids, stats, centroids, 8, CV_32S);
  std::vector<char> big(static_cast<std::size_t>(n), 0);
  for (int k = 1; k < n; ++k)
    big[static_cast<std::size_t>(k)] = std::max(stats(k, cv::CC_STAT_WIDTH), stats(k, cv::CC_STAT_HEIGHT)) >= min_cells;
  cv::Mat1b out(grid.rows, grid.cols, static_cast<std::uint8_t>(0));
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (big[static_cast<std::size_t>(ids(r, c))]) out(r, c) = 255;
  return out;
}

// The row and column scans (Cuts::scan) in the building's own frame: the map and the labels are
// turned by `angle` (nearest neighbour, on a canvas grown to hold them, unknown and unlabelled
// beyond), scanned, and the cut cells turned back; each is widened to its 4-neighbours so that a
// cut line turned back by nearest neighbour still parts its segment in 4-connected pieces, and
// kept where the map is free and labelled.
cv::Mat1b aligned_scan_cuts(const ClassGrid& grid, const cv::Mat1w& label, const Cuts& like, double min_wall_cells,
                            double angle) {
  const double deg = angle * 180.0 / CV_PI;
  const cv::Point2f centre(0.5f * static_cast<float>(grid.cols - 1), 0.5f * static_cast<float>(grid.rows - 1));
  cv::Mat rot = cv::getRotationMatrix2D(centre, deg, 1.0);
  const double ca = std::abs(std::cos(angle)), sa = std::abs(std::sin(angle));
  const cv::Size size(static_cast<int>(std::ceil(grid.cols * ca + grid.rows * sa)),
                      static_cast<int>(std::ceil(grid.cols * sa + grid.rows * ca)));
  rot.at<double>(0, 2) += 0.5 * (size.width - 1) - centre.x;
  rot.at<double>(1, 2) += 0.5 * (size.height - 1) - centre.y;
  ClassGrid turned_grid;
  cv::Mat1w turned_label;
  cv::warpAffine(grid, turned_grid, rot, size, cv::INTER_NEAREST, cv::BORDER_CONSTANT,
                 cv::Scalar(static_cast<double>(Cell::Unknown)));
  cv::warpAffine(label, turned_label, rot, size, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
  Cuts turned{turned_grid, turned_label, like.run, like.thick, like.max_gap,
              cv::Mat1b(size, static_cast<std::uint8_t>(0)), wall_pieces(turned_grid, min_wall_cells), 2};
  turned.scan(0, 1);
  turned.scan(1, 0);
  cv::Mat1b back;
  cv::warpAffine(turned.cut, back, rot, grid.size(), cv::INTER_NEAREST | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT,
                 cv::Scalar(0));
  cv::dilate(back, back, cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3)));
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (back(r, c) && (grid(r, c) != static_cast<std::uint8_t>(Cell::Free) || label(r, c) == 0)) back(r, c) = 0;
  return back;
}

// A corridor continues (split_at_wall_gaps in wall_gap_cuts.h): where an 8-connected piece of
// `cut` crosses a corridor-shaped unit from side to side, the crossing is erased. A piece crosses
// unit u when at least 90 % of its cells lie in u (or within 2 cells of it) and they, or a strand
// of them (a run of u's cross-sections they fill to half its width), lie within kMaxCrossCut along
// u and span u's width across u but for kSideSlack at each side (the slack of the unit's edges; a
// door frame's stubs narrow the corridor more) and at least kCorridorSpan of it, with u going on
// for at least its width beyond them at both ends, and walled there: on each side, at least a
// third of the cross-sections 1/2 to 3/2 widths away (one per cell) are free runs from wall to
// wall no longer than u's width and the slack (doors in the corridor's walls open the others). A piece that crosses as a whole is erased whole; of a longer
// piece (a cut across that touches the cuts of door gaps in the corridor's walls at its ends:
// Freiburg79_scan once its specks are cleared) only the strand. A cut where a corridor piece ends
// in a crossing corridor, or opens into a room, stays (NLB: a side passage whose unit runs on
// through the main corridor is a room of its own).
void keep_corridors_whole(const ClassGrid& grid, cv::Mat1b& cut, const std::vector<UnitResult>& units, double res) {
  struct Corridor {
    Quad q;
    Point2 across, along;  // unit vectors: the short side's direction, the long side's
    double width;          // cells
    double end0, end1;     // the unit's ends, as coordinates along `along`
  };
  std::vector<Corridor> corridors;
  for (const auto& u : units) {
    const double w = corridor_width(u.corners, res);
    if (!std::isfinite(w)) continue;
    const auto& q = u.corners;
    Point2 e1{q[1].x - q[0].x, q[1].y - q[0].y}, e2{q[2].x - q[1].x, q[2].y - q[1].y};
    const double l1 = std::hypot(e1.x, e1.y), l2 = std::hypot(e2.x, e2.y);
    e1 = {e1.x / l1, e1.y / l1};
    e2 = {e2.x / l2, e2.y / l2};
    Corridor co = l1 <= l2 ? Corridor{q, e1, e2, w, 0.0, 0.0} : Corridor{q, e2, e1, w, 0.0, 0.0};
    co.end0 = std::numeric_limits<double>::infinity();
    co.end1 = -co.end0;
    for (const Point2& p : q) {
      const double t = p.x * co.along.x + p.y * co.along.y;
      co.end0 = std::min(co.end0, t), co.end1 = std::max(co.end1, t);
    }
    corridors.push_back(co);
  }
  if (corridors.empty()) return;
  cv::Mat1i ids, stats;
  cv::Mat centroids;
  const int n = cv::connectedComponentsWithStats(cut, ids, stats, centroids, 8, CV_32S);
  const double max_along = kMaxCrossCut / res, slack = 2.0 * kSideSlack / res;
  const auto is_free = [&grid](const Point2& p) {
    const int r = static_cast<int>(std::lround(p.y)), c = static_cast<int>(std::lround(p.x));
    return r >= 0 && c >= 0 && r < grid.rows && c < grid.cols && grid(r, c) == static_cast<std::uint8_t>(Cell::Free);
  };
  // The free run across co through p, in cells; infinity past the limit.
  const auto cross_run = [&](const Corridor& co, Point2 p, double limit) {
    if (!is_free(p)) return std::numeric_limits<double>::infinity();
    double run = 1.0;
    for (const int s : {-1, 1})
      for (double k = 1.0; is_free({p.x + s * k * co.across.x, p.y + s * k * co.across.y}); k += 1.0)
        if (++run > limit) return std::numeric_limits<double>::infinity();
    return run;
  };
  const auto walled = [&](const Corridor& co, Point2 centre, int side) {
    int samples = 0, walls = 0;
    for (double k = 0.5 * co.width; k <= 1.5 * co.width; k += 1.0, ++samples) {
      const Point2 p{centre.x + side * k * co.along.x, centre.y + side * k * co.along.y};
      if (cross_run(co, p, co.width + slack + 2.0) <= co.width + slack + 2.0) ++walls;
    }
    return 3 * walls >= samples;
  };
  for (int k = 1; k < n; ++k) {
    const int x0 = stats(k, cv::CC_STAT_LEFT), y0 = stats(k, cv::CC_STAT_TOP);
    const int x1 = x0 + stats(k, cv::CC_STAT_WIDTH), y1 = y0 + stats(k, cv::CC_STAT_HEIGHT);
    std::vector<Point2> cells;
    for (int r = y0; r < y1; ++r)
      for (int c = x0; c < x1; ++c)
        if (ids(r, c) == k) cells.push_back({static_cast<double>(c), static_cast<double>(r)});
    // Whether `part` (cells of the piece in co) crosses co; see above.
    const auto crosses = [&](const Corridor& co, const std::vector<Point2>& part) {
      double a0 = std::numeric_limits<double>::infinity(), a1 = -a0, l0 = a0, l1 = -a0;
      for (const Point2& p : part) {
        const double a = p.x * co.across.x + p.y * co.across.y, l = p.x * co.along.x + p.y * co.along.y;
        a0 = std::min(a0, a), a1 = std::max(a1, a), l0 = std::min(l0, l), l1 = std::max(l1, l);
      }
      const double mid = 0.5 * (l0 + l1);
      if (part.empty() || a1 - a0 + 1.0 < std::max(kCorridorSpan * co.width, co.width - slack) ||
          l1 - l0 + 1.0 > max_along || std::min(mid - co.end0, co.end1 - mid) < co.width)
        return false;
      const Point2 centre{(a0 + a1) * 0.5 * co.across.x + mid * co.along.x, (a0 + a1) * 0.5 * co.across.y + mid * co.along.y};
      return walled(co, centre, -1) && walled(co, centre, +1);
    };
    // The piece is erased when its cells in co cross it. Else its strands are: runs of
    // consecutive cross-sections of co (one per cell along it) in which its cells fill at least
    // half of co's width: a cut across that touches the cuts of door gaps in the corridor's
    // walls at its ends (8-connected) has the cut across as its strand, and the door gaps fill
    // one or two cells of a cross-section.
    const auto erase_crossings = [&](const Corridor& co) {
      std::vector<Point2> inside;
      for (const Point2& p : cells)
        if (depth_inside(co.q, p) >= -2.0) inside.push_back(p);
      if (inside.empty() || 10 * inside.size() < 9 * cells.size()) return false;
      if (crosses(co, inside)) {  // with its few cells outside co
        for (const Point2& p : cells) cut(static_cast<int>(p.y), static_cast<int>(p.x)) = 0;
        return true;
      }
      std::map<long, std::vector<Point2>> section;  // along co, rounded -> the piece's cells there
      for (const Point2& p : inside) section[std::lround(p.x * co.along.x + p.y * co.along.y)].push_back(p);
      const auto full = [&co](const std::vector<Point2>& cs) { return 2.0 * static_cast<double>(cs.size()) >= co.width; };
      bool erased = false;
      for (auto it = section.begin(); it != section.end();) {
        if (!full(it->second)) {
          ++it;
          continue;
        }
        std::vector<Point2> strand = it->second;
        auto next = std::next(it);
        for (; next != section.end() && next->first == std::prev(next)->first + 1 && full(next->second); ++next)
          strand.insert(strand.end(), next->second.begin(), next->second.end());
        if (crosses(co, strand)) {
          for (const Point2& p : strand) cut(static_cast<int>(p.y), static_cast<int>(p.x)) = 0;
          erased = true;
        }
        it = next;
      }
      return erased;
    };
    for (const Corridor& co : corridors)
      if (erase_crossings(co)) break;
  }
}

}  // namespace

double dominant_wall_angle(const WorldResult& w) {
  // Each unit's edge direction in [-45, 45) degrees (period 90) and its area; the unit direction
  // with the most area within kNearDirection of it; the area-weighted mean direction there.
  std::vector<std::pair<double, double>> dirs;
  double total = 0.0;
  for (const auto& u : w.units) {
    const auto& q = u.corners;
    const double ex = q[1].x - q[0].x, ey = q[1].y - q[0].y;
    const double area = std::abs(ex * (q[2].y - q[1].y) - ey * (q[2].x - q[1].x));
    if (!std::isfinite(area) || !(area > 0.0)) continue;
    double deg = std::atan2(ey, ex) * 180.0 / CV_PI;
    deg -= 90.0 * std::floor((deg + 45.0) / 90.0);
    dirs.emplace_back(deg, area);
    total += area;
  }
  const auto offset = [](double a, double b) { return a - b - 90.0 * std::round((a - b) / 90.0); };  // a - b in [-45, 45]
  double best = 0.0, centre = 0.0;
  for (const auto& [d, area] : dirs) {
    double near = 0.0;
    for (const auto& [e, other] : dirs)
      if (detect::angle_diff_mod90(e, d) <= kNearDirection) near += other;
    if (near > best) best = near, centre = d;
  }
  // Units at several directions (office_e's pentagon): no one frame; rows and columns.
  if (!(total > 0.0) || best < kMinShare * total) return 0.0;
  double sum = 0.0;
  for (const auto& [e, area] : dirs)
    if (detect::angle_diff_mod90(e, centre) <= kNearDirection) sum += area * offset(e, centre);
  double deg = centre + sum / best;
  deg -= 90.0 * std::floor((deg + 45.0) / 90.0);
  return deg * CV_PI / 180.0;
}

void split_at_wall_gaps(const ClassGrid& grid, double resolution, cv::Mat1w& label, const cv::Mat1w* before_join,
                        double wall_angle, const std::vector<UnitResult>* units) {
  const double res = resolution > 0.0 ? resolution : 0.05;
  const bool aligned = std::abs(wall_angle) < kAlignedAngle;
  // The wall pieces are read only by the row and column scans, which run on this grid when the
  // building is aligned with it (aligned_scan_cuts finds those of the turned grid).
  Cuts cuts{grid, label, std::max(1, static_cast<int>(std::lround(kWallRun / res))),
            std::max(1, static_cast<int>(std::lround(kMaxWallThickness / res))),
            static_cast<int>(std::lround(kMaxGap / res)), cv::Mat1b(grid.rows, grid.cols, static_cast<std::uint8_t>(0)),
            aligned ? wall_pieces(grid, kMinWallPiece / res) : cv::Mat1b()};
  if (aligned) {
    cuts.scan(0, 1);
    cuts.scan(1, 0);
  } else {
    cuts.cut |= aligned_scan_cuts(grid, label, cuts, kMinWallPiece / res, wall_angle);
  }
  cuts.cut_lines(thin_wall_lines(grid, res), kMaxEndGap / res, 1.0 / res);
  if (units != nullptr) keep_corridors_whole(grid, cuts.cut, *units, res);
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
  std::vector<int> cut_off;  // the large pieces that lose their segment's id
  for (auto& [id, ps] : large) {
    if (ps.size() < 2) continue;
    split_segment[static_cast<std::size_t>(id)] = 1;
    const auto biggest = *std::max_element(ps.begin(), ps.end(), [&](int a, int b) { return area[a] < area[b]; });
    for (const int p : ps) {
      if (p == biggest) target[static_cast<std::size_t>(p)] = id;
      else cut_off.push_back(p);
    }
  }
  // A piece cut off gets back the id its cells mostly had before the join when no segment uses
  // it now (and no other piece took it), else a new id above every id in use now or before.
  int next = max_id;
  std::map<int, std::map<int, long>> votes;  // cut-off piece -> id before the join -> cells
  std::vector<char> in_use(0x10000, 0);
  if (before_join != nullptr && !cut_off.empty()) {
    for (const int p : cut_off) votes[p];
    for (int r = 0; r < label.rows; ++r)
      for (int c = 0; c < label.cols; ++c) {
        const int before = (*before_join)(r, c);
        in_use[label(r, c)] = 1;
        next = std::max(next, before);
        if (const auto v = votes.find(piece(r, c)); before != 0 && v != votes.end()) ++v->second[before];
      }
  }
  for (const int p : cut_off) {
    int& t = target[static_cast<std::size_t>(p)];
    if (const auto v = votes.find(p); v != votes.end() && !v->second.empty()) {
      const int earlier = std::max_element(v->second.begin(), v->second.end(), [](const auto& x, const auto& y) { return x.second < y.second; })->first;
      if (!in_use[static_cast<std::size_t>(earlier)]) {
        t = earlier;
        in_use[static_cast<std::size_t>(earlier)] = 1;
        continue;
      }
    }
    t = next < 0xffff ? ++next : owner[static_cast<std::size_t>(p)];
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
