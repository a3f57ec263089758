// Scene → the geometric relations of every body and pair of bodies, with one set of
// tolerances: stable, hover, the table, contact, intersect, higher (the scene graph's
// support and contact edges are read from them, result.h). Bodies are the table (index 0,
// id "table") followed by the scene's objects in file order (index i + 1); contact and
// intersect are symmetric. A domain's evidence is what its generated extractors compute
// (blocks.h); these matrices use the same relations.
#pragma once

#include <string>
#include <vector>

#include "stdlib/tabletop/evidence_params.h"
#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pair_geometry.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct Evidence {
  std::vector<std::string> ids;  // body ids: "table", then objects
  std::vector<Obb> boxes;
  std::vector<char> stable, hover, is_table;
  std::vector<std::vector<char>> contact, intersect, higher;  // [a][b]
  std::vector<std::vector<PairGeometry>> geometry;             // [a][b], a != b

  [[nodiscard]] std::size_t size() const { return ids.size(); }
  // Body index of an object index.
  static std::size_t body(std::size_t object_index) { return object_index + 1; }
};

Evidence extract_evidence(const Scene& scene, const EvidenceParams& params = {});

// Re-extracts after scene.objects[object_index] moved: stable of that object, every
// pair involving it, and hover of all bodies (hover depends on those pairs).
void update_evidence(Evidence& ev, const Scene& scene, std::size_t object_index,
                     const EvidenceParams& params = {});

}  // namespace ksmc::stdlib::tabletop
