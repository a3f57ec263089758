#include "stdlib/indoor/io/segmentation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "runtime/io/atomic_file.h"
#include "stdlib/indoor/io/corridor_shape.h"
#include "stdlib/indoor/io/doorway_spaces.h"
#include "stdlib/indoor/io/quad.h"
#include "stdlib/indoor/io/thin_walls.h"  // kMaxWallThickness
#include "stdlib/indoor/io/unit_chains.h"
#include "stdlib/indoor/io/wall_gap_cuts.h"
#include "stdlib/indoor/io/world_images.h"
#include "stdlib/indoor/io/world_json.h"

namespace ksmc::stdlib::indoor::io {

namespace {

// The spaces no unit reaches: the free cells farther than kPassageHalfWidth from every wall or
// unknown cell (the map's free space with its passages narrower than a door cut off), grouped
// in 4-connected components. A component that holds no cell a unit explains, and is at least
// kMinCoreArea large, is a space of its own behind a narrow passage: its cells get a new id
// (above every unit id) and seed the nearest-space fill with the units. Without this the fill
// gives a whole uncovered room, through its door, to a unit of the next room.
constexpr double kPassageHalfWidth = 0.6;  // m: passages up to 1.2 m wide (a door and its frame)
constexpr double kMinCoreArea = 0.5;       // m^2 of cells farther than that from every wall

// The free cells farther than kPassageHalfWidth from every wall or unknown cell (255), else 0.
cv::Mat1b open_core(const ClassGrid& grid, double res) {
  cv::Mat1b free_mask(grid.rows, grid.cols);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) free_mask(r, c) = grid(r, c) == static_cast<std::uint8_t>(Cell::Free) ? 255 : 0;
  cv::Mat1f dist;
  cv::distanceTransform(free_mask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return dist > static_cast<float>(kPassageHalfWidth / res);
}

void seed_uncovered_spaces(const ClassGrid& grid, const WorldResult& w, cv::Mat1w& label) {
  const double res = w.map.resolution > 0.0 ? w.map.resolution : 0.05;
  const cv::Mat1b core = open_core(grid, res);
  cv::Mat1i comp;
  const int n = cv::connectedComponents(core, comp, 4, CV_32S);
  std::vector<char> covered(static_cast<std::size_t>(n), 0);
  std::vector<long> area(static_cast<std::size_t>(n), 0);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) {
      const auto k = static_cast<std::size_t>(comp(r, c));
      if (k == 0) continue;
      ++area[k];
      if (label(r, c) != 0) covered[k] = 1;
    }
  int next = 0;
  for (const auto& u : w.units) next = std::max(next, u.id);
  const double min_cells = kMinCoreArea / (res * res);
  std::vector<int> id(static_cast<std::size_t>(n), 0);
  for (int k = 1; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (!covered[i] && static_cast<double>(area[i]) >= min_cells && next < 0xffff) id[i] = ++next;
  }
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (const int k = id[static_cast<std::size_t>(comp(r, c))]; k != 0) label(r, c) = static_cast<std::uint16_t>(k);
}

// A free component that no unit and no space reaches (a small room or a narrow one, whose
// cells all lie within kPassageHalfWidth of a wall, seen by no unit) is a space of its own when
// it is at least kMinLoneArea large: it is free floor a robot can stand on, in no other
// segment. Smaller components (scan speckle) stay 0.
constexpr double kMinLoneArea = 0.25;  // m^2

void label_unreached_components(const ClassGrid& grid, double resolution, cv::Mat1w& label) {
  const double res = resolution > 0.0 ? resolution : 0.05;
  const auto min_cells = static_cast<std::size_t>(std::ceil(kMinLoneArea / (res * res)));
  int next = 0;
  for (int r = 0; r < label.rows; ++r)
    for (int c = 0; c < label.cols; ++c) next = std::max<int>(next, label(r, c));
  cv::Mat1b seen(grid.rows, grid.cols, static_cast<std::uint8_t>(0));
  std::vector<std::pair<int, int>> comp, stack;
  constexpr int kDr[4] = {-1, 0, 0, 1}, kDc[4] = {0, -1, 1, 0};
  const auto open = [&](int r, int c) {
    return grid(r, c) == static_cast<std::uint8_t>(Cell::Free) && label(r, c) == 0 && !seen(r, c);
  };
  for (int r0 = 0; r0 < grid.rows; ++r0)
    for (int c0 = 0; c0 < grid.cols; ++c0) {
      if (!open(r0, c0)) continue;
      comp.clear();
      stack.assign(1, {r0, c0});
      seen(r0, c0) = 1;
      while (!stack.empty()) {
        const auto [r, c] = stack.back();
        stack.pop_back();
        comp.emplace_back(r, c);
        for (int k = 0; k < 4; ++k) {
          const int nr = r + kDr[k], nc = c + kDc[k];
          if (nr < 0 || nc < 0 || nr >= grid.rows || nc >= grid.cols || !open(nr, nc)) continue;
          seen(nr, nc) = 1;
          stack.emplace_back(nr, nc);
        }
      }
      if (comp.size() < min_cells || next >= 0xffff) continue;
      ++next;
      for (const auto& [r, c] : comp) label(r, c) = static_cast<std::uint16_t>(next);
    }
}

// Two segments that meet over more than kOpenJoin of free cells are one space, as the
// `@one_space` rule of domains/indoor.ksm says of units (a free run over 2 m): furniture cuts an
// uncovered room's core into pieces, a door does not join two rooms that wide. Two units (the
// chain's rectangles) are joined only when, besides, no wall separates them:
//   * more than kOpenCore of their contact lies in open_core (both cells over 0.6 m from every
//     wall or unknown cell: an opening wider than a door frame, not a jagged fill boundary
//     running through a door), and
//   * the wall runs between them (a free cell of one, at most kMaxWallThickness of occupied
//     cells along a row or column, a free cell of the other) are at most kWallShare of their
//     free contact: two rooms with a wide opening in the wall between them share a long wall;
//     a room the chain covered with a unit and a sliver, or a corridor in pieces, does not; and
//   * the smaller of the two is under kMaxJoinedPiece: a piece of a room (a sliver along its
//     edge, one end of a corridor), not a room of its own; without it a corridor unit swallows
//     the offices whose units reach into it (office_h: corridor and 10 offices one segment).
// A corridor continues: two corridor-shaped units (each under kNarrowUnit across, or under
// kLongUnit and kLongRatio times as long) whose free contact spans more than kEndShare of the
// narrower one's width, and more than a door (kDoorWidth), are one space whatever their size,
// when the wall runs between them are at most kWallShare of the contact (the `@one_space`
// rule's 3/4 of the join for a corridor cut across). A corridor in a ring or an L is several
// rectangles meeting end to side; its contact is the corridor's width, often under 2 m, and too
// close to the walls for open_core (office_a: a ring in 6 pieces).
// Units that continue each other (unit_chains.h: facing sides that meet over the whole free
// passage between them) are one space whatever their size and contact: a corridor 1.35 m wide in
// pieces (lab_b_scan) meets its next piece over no more than a door's width, and the pieces of
// office_h's 3.8 m ring corridor are each larger than kMaxJoinedPiece.
// Pairs are joined widest contact first. split_at_wall_gaps runs afterwards and cuts again
// where a straight wall line with a gap crosses a joined segment.
constexpr double kOpenJoin = 2.0;           // m of free contact
constexpr double kOpenCore = 0.5;           // m of contact in open_core, for two units
constexpr double kWallShare = 0.25;         // wall runs / free contact pairs, for two units
constexpr double kMaxJoinedPiece = 20.0;    // m^2, for two units
constexpr double kEndShare = 0.75;          // of the narrower unit's width, for two corridor-shaped units
constexpr double kDoorWidth = 1.2;          // m: a contact no wider is a doorway

using PairCount = std::map<std::pair<int, int>, long>;  // (smaller, larger id) -> count

// Wall runs between two different segments along rows and columns.
PairCount wall_contacts(const ClassGrid& grid, double res, const cv::Mat1w& label) {
  PairCount out;
  const int thick = std::max(1, static_cast<int>(std::lround(kMaxWallThickness / res)));
  for (const bool rows : {true, false}) {
    const int lines = rows ? label.rows : label.cols, len = rows ? label.cols : label.rows;
    for (int l = 0; l < lines; ++l) {
      int prev = 0, wall = 0;
      for (int k = 0; k < len; ++k) {
        const int r = rows ? l : k, c = rows ? k : l;
        if (grid(r, c) == static_cast<std::uint8_t>(Cell::Occupied)) {
          ++wall;
          continue;
        }
        const int cur = label(r, c);
        if (cur != 0 && prev != 0 && cur != prev && wall > 0 && wall <= thick) ++out[{std::min(cur, prev), std::max(cur, prev)}];
        prev = cur;
        wall = 0;
      }
    }
  }
  return out;
}

// The id each joined set of units keeps (root -> id): of the unit types in it, the one whose
// units hold most of its cells (ties: the type first by name); of that type's units, the one
// with the largest segment of its own (ties: the smaller id). A corridor joined from pieces the
// rule base typed differently keeps the id, and so the type, of most of its length. `area`:
// cells per id before the join; `find`: the union-find root of an id. Sets of spaces only are
// not listed (they keep their root, the smallest id).
template <class Find>
std::map<int, int> kept_ids(const WorldResult& w, int max_unit, const std::map<int, long>& area, const Find& find) {
  std::map<int, const UnitResult*> unit_of;
  for (const auto& u : w.units) unit_of[u.id] = &u;
  std::map<int, std::map<std::string, long>> type_cells;  // root -> type -> cells
  std::map<int, std::vector<int>> members;                // root -> its unit ids, ascending
  for (const auto& [id, cells] : area) {
    if (id == 0 || id > max_unit || !unit_of.count(id)) continue;
    type_cells[find(id)][unit_of[id]->type] += cells;
    members[find(id)].push_back(id);
  }
  std::map<int, int> keep;
  for (const auto& [root, ids] : members) {
    const auto& tc = type_cells[root];
    const std::string& main_type =
        std::max_element(tc.begin(), tc.end(), [](const auto& x, const auto& y) { return x.second < y.second; })->first;
    int best = 0;
    for (const int id : ids)
      if (unit_of[id]->type == main_type && (best == 0 || area.at(id) > area.at(best))) best = id;
    keep[root] = best;
  }
  return keep;
}

void merge_open_spaces(const ClassGrid& grid, const WorldResult& w, cv::Mat1w& label) {
  const double res = w.map.resolution > 0.0 ? w.map.resolution : 0.05;
  int max_unit = 0;
  for (const auto& u : w.units) max_unit = std::max(max_unit, u.id);
  const cv::Mat1b core = open_core(grid, res);
  PairCount contact, core_contact;  // 4-neighbour cell pairs, all / both in open_core
  const auto touch = [&](int a, int b, bool in_core) {
    if (a == 0 || b == 0 || a == b) return;
    const std::pair<int, int> ab{std::min(a, b), std::max(a, b)};
    ++contact[ab];
    if (in_core) ++core_contact[ab];
  };
  for (int r = 0; r < label.rows; ++r)
    for (int c = 0; c < label.cols; ++c) {
      if (c + 1 < label.cols) touch(label(r, c), label(r, c + 1), core(r, c) && core(r, c + 1));
      if (r + 1 < label.rows) touch(label(r, c), label(r + 1, c), core(r, c) && core(r + 1, c));
    }
  const PairCount walls = wall_contacts(grid, res, label);
  std::map<int, long> area;
  for (int r = 0; r < label.rows; ++r)
    for (int c = 0; c < label.cols; ++c) ++area[label(r, c)];
  std::map<int, double> width;  // unit id -> corridor_width (infinity: not corridor-shaped)
  for (const auto& u : w.units) width[u.id] = corridor_width(u.corners, res);
  const auto corridor_join = [&](const std::pair<int, int>& ab, long n) {
    const auto wa = width.find(ab.first), wb = width.find(ab.second);
    if (wa == width.end() || wb == width.end()) return false;
    if (!std::isfinite(wa->second) || !std::isfinite(wb->second)) return false;
    const double narrower = std::min(wa->second, wb->second) * res;
    const double run = static_cast<double>(n) * res;
    if (run <= kDoorWidth || run <= kEndShare * narrower) return false;
    const auto wc = walls.find(ab);
    return wc == walls.end() || static_cast<double>(wc->second) <= kWallShare * static_cast<double>(n);
  };
  std::vector<std::pair<long, std::pair<int, int>>> joins;
  // Units that continue each other (unit_chains.h): one space whatever their contact.
  const std::vector<std::pair<int, int>> continued = continued_units(grid, w.units);
  for (const auto& ab : continued)
    if (const auto it = contact.find(ab); it != contact.end()) joins.push_back({it->second, ab});
  for (const auto& [ab, n] : contact) {
    if (std::binary_search(continued.begin(), continued.end(), ab)) continue;
    if (ab.second <= max_unit && corridor_join(ab, n)) {
      joins.push_back({n, ab});
      continue;
    }
    if (static_cast<double>(n) * res <= kOpenJoin) continue;
    if (ab.second <= max_unit) {  // two units
      if (static_cast<double>(std::min(area[ab.first], area[ab.second])) * res * res >= kMaxJoinedPiece) continue;
      const auto cc = core_contact.find(ab);
      const auto wc = walls.find(ab);
      if (cc == core_contact.end() || static_cast<double>(cc->second) * res <= kOpenCore) continue;
      if (wc != walls.end() && static_cast<double>(wc->second) > kWallShare * static_cast<double>(n)) continue;
    }
    joins.push_back({n, ab});
  }
  std::stable_sort(joins.begin(), joins.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::map<int, int> parent;  // union-find over ids; a set's root is its smallest unit id when it has one (kept_ids renames it)
  const auto find = [&parent](int a) {
    while (true) {
      const auto it = parent.find(a);
      if (it == parent.end() || it->second == a) return a;
      a = it->second;
    }
  };
  for (const auto& [n, ab] : joins) {
    const int ra = find(ab.first), rb = find(ab.second);
    if (ra == rb) continue;
    const bool a_first = ra <= max_unit ? (rb > max_unit || ra < rb) : (rb > max_unit && ra < rb);
    if (a_first) parent[rb] = ra;
    else parent[ra] = rb;
  }
  if (parent.empty()) return;
  const std::map<int, int> keep = kept_ids(w, max_unit, area, find);
  for (int r = 0; r < label.rows; ++r)
    for (int c = 0; c < label.cols; ++c)
      if (label(r, c) != 0) {
        const int root = find(label(r, c));
        const auto k = keep.find(root);
        label(r, c) = static_cast<std::uint16_t>(k != keep.end() ? k->second : root);
      }
}

// Furniture is part of its room (the benchmark's ground truth, and a robot's map, count the
// floor under a table as the room's): an occupied 8-connected blob of at most kMaxFurniture
// that touches no map edge and whose 4-neighbours are all free cells of one segment gets that
// segment. Walls are one large structure touching several segments (or unknown space), and
// furniture standing against a wall is part of that structure, so both stay 0.
constexpr double kMaxFurniture = 4.0;  // m^2: a large table

void fill_furniture(const ClassGrid& grid, const WorldResult& w, cv::Mat1w& label) {
  const double res = w.map.resolution > 0.0 ? w.map.resolution : 0.05;
  const auto max_cells = static_cast<std::size_t>(kMaxFurniture / (res * res));
  cv::Mat1b seen(grid.rows, grid.cols, static_cast<std::uint8_t>(0));
  std::vector<std::pair<int, int>> blob, stack;
  const auto occupied = [&grid](int r, int c) { return grid(r, c) == static_cast<std::uint8_t>(Cell::Occupied); };
  for (int r0 = 0; r0 < grid.rows; ++r0)
    for (int c0 = 0; c0 < grid.cols; ++c0) {
      if (!occupied(r0, c0) || seen(r0, c0)) continue;
      blob.clear();
      stack.assign(1, {r0, c0});
      seen(r0, c0) = 1;
      bool edge = false, mixed = false;
      int owner = 0;
      while (!stack.empty()) {
        const auto [r, c] = stack.back();
        stack.pop_back();
        blob.emplace_back(r, c);
        if (r == 0 || c == 0 || r == grid.rows - 1 || c == grid.cols - 1) edge = true;
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int nr = r + dr, nc = c + dc;
            if ((dr == 0 && dc == 0) || nr < 0 || nc < 0 || nr >= grid.rows || nc >= grid.cols) continue;
            if (occupied(nr, nc)) {
              if (!seen(nr, nc)) {
                seen(nr, nc) = 1;
                stack.emplace_back(nr, nc);
              }
            } else if (dr == 0 || dc == 0) {
              const int l = label(nr, nc);
              if (grid(nr, nc) != static_cast<std::uint8_t>(Cell::Free) || l == 0 || (owner != 0 && l != owner)) mixed = true;
              else owner = l;
            }
          }
      }
      if (edge || mixed || owner == 0 || blob.size() > max_cells) continue;
      for (const auto& [r, c] : blob) label(r, c) = static_cast<std::uint16_t>(owner);
    }
}

}  // namespace

cv::Mat1w render_segmentation(const ClassGrid& grid, const WorldResult& w) {
  validate_world(w, false);
  if (grid.empty()) throw std::invalid_argument("segmentation: empty map");
  const auto free_cell = [&grid](int r, int c) { return grid(r, c) == static_cast<std::uint8_t>(Cell::Free); };
  cv::Mat1i owner(grid.rows, grid.cols, -1);  // index into w.units
  cv::Mat1f depth(grid.rows, grid.cols, 0.0f);
  std::vector<Point2> centre(w.units.size());
  for (std::size_t i = 0; i < w.units.size(); ++i) {
    const auto& u = w.units[i];
    if (!finite_quad(u.corners)) continue;
    const auto& q = u.corners;
    centre[i] = {(q[0].x + q[1].x + q[2].x + q[3].x) / 4.0, (q[0].y + q[1].y + q[2].y + q[3].y) / 4.0};
    double x0 = q[0].x, x1 = q[0].x, y0 = q[0].y, y1 = q[0].y;
    for (const auto& p : q) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    const int c0 = std::max(0, static_cast<int>(std::ceil(x0))), c1 = std::min(grid.cols - 1, static_cast<int>(std::floor(x1)));
    const int r0 = std::max(0, static_cast<int>(std::ceil(y0))), r1 = std::min(grid.rows - 1, static_cast<int>(std::floor(y1)));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        if (!free_cell(r, c)) continue;
        const Point2 p{static_cast<double>(c), static_cast<double>(r)};
        const auto d = static_cast<float>(depth_inside(q, p));
        if (!(d > 0.0f)) continue;
        int& o = owner(r, c);
        float& best = depth(r, c);
        bool take = o < 0 || d > best;
        if (!take && d == best) {  // tie: the nearer centre, then the smaller id
          const auto j = static_cast<std::size_t>(o);
          const double di = std::hypot(p.x - centre[i].x, p.y - centre[i].y);
          const double dj = std::hypot(p.x - centre[j].x, p.y - centre[j].y);
          take = di < dj || (di == dj && u.id < w.units[j].id);
        }
        if (take) {
          o = static_cast<int>(i);
          best = d;
        }
      }
    }
  }
  cv::Mat1w label(grid.rows, grid.cols, static_cast<std::uint16_t>(0));
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (const int o = owner(r, c); o >= 0) label(r, c) = static_cast<std::uint16_t>(w.units[static_cast<std::size_t>(o)].id);
  seed_uncovered_spaces(grid, w, label);
  const cv::Mat1b explained = label != 0;
  // Multi-source BFS over 4-connected free cells from every labelled cell, row-major order.
  std::deque<std::pair<int, int>> queue;
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c)
      if (label(r, c) != 0) queue.emplace_back(r, c);
  constexpr int kDr[4] = {-1, 0, 0, 1}, kDc[4] = {0, -1, 1, 0};
  while (!queue.empty()) {
    const auto [r, c] = queue.front();
    queue.pop_front();
    for (int k = 0; k < 4; ++k) {
      const int nr = r + kDr[k], nc = c + kDc[k];
      if (nr < 0 || nc < 0 || nr >= grid.rows || nc >= grid.cols) continue;
      if (label(nr, nc) != 0 || !free_cell(nr, nc)) continue;
      label(nr, nc) = label(r, c);
      queue.emplace_back(nr, nc);
    }
  }
  detach_spaces_behind_doorways(grid, w.map.resolution, explained, label);
  label_unreached_components(grid, w.map.resolution, label);
  const cv::Mat1w before_join = label.clone();
  merge_open_spaces(grid, w, label);
  split_at_wall_gaps(grid, w.map.resolution, label, &before_join, dominant_wall_angle(w), &w.units);
  fill_furniture(grid, w, label);
  return label;
}

void write_segmentation_png(const std::filesystem::path& path, const ClassGrid& grid, const WorldResult& w) {
  runtime::io::write_file_atomic(path, encode_png(render_segmentation(grid, w), path.string()));
}

}  // namespace ksmc::stdlib::indoor::io
