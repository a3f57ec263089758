// Scene → ground evidence atoms for the table-top MLN:
//   stable(o), table(o), hover(o), contact(a,b), intersect(a,b), higher(a,b).
// Bodies are the table (index 0, id "table") followed by the scene's objects in
// file order (index i + 1). Only true atoms are listed (closed world); contact and
// intersect are listed in both argument orders (rules r4, r5).
#pragma once

#include <string>
#include <vector>

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pair_geometry.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct GroundAtom {
  std::string predicate;
  std::vector<std::string> args;
  bool operator==(const GroundAtom&) const = default;
  auto operator<=>(const GroundAtom&) const = default;
};

struct Evidence {
  std::vector<std::string> ids;  // body ids: "table", then objects
  std::vector<Obb> boxes;
  std::vector<char> stable, hover, is_table;
  std::vector<std::vector<char>> contact, intersect, higher;  // [a][b]
  std::vector<std::vector<PairGeometry>> geometry;             // [a][b], a != b

  [[nodiscard]] std::size_t size() const { return ids.size(); }
  // Body index of an object index.
  static std::size_t body(std::size_t object_index) { return object_index + 1; }
  // Ground atoms in a fixed order: table, stable, hover, contact, intersect, higher;
  // bodies in index order within each predicate.
  [[nodiscard]] std::vector<GroundAtom> atoms() const;
};

Evidence extract_evidence(const Scene& scene, const EvidenceParams& params = {});

// Re-extracts after scene.objects[object_index] moved: stable of that object, every
// pair involving it, and hover of all bodies (hover depends on those pairs).
void update_evidence(Evidence& ev, const Scene& scene, std::size_t object_index,
                     const EvidenceParams& params = {});

}  // namespace ksmc::stdlib::tabletop
