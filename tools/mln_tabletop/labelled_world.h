// A simulated table-top scene (ksmc-scenegen's scene_NNN.json + scene_NNN.truth.json) as
// one labelled world of domains/tabletop.ksm, in .db text: the evidence atoms the
// domain's extractors compute from the estimated boxes (stdlib/tabletop/evidence.h, the
// same tolerances), and the true query atoms (closed world: unlisted ones are false):
//   falseEst(o), hidden(o)    the generator's truth;
//   supported(a), supportive(b)  for each true support edge (a on b, b maybe the table),
//                             and for each pair the hard rule r10 derives from the
//                             evidence (stable a, b in contact, a higher): those atoms are
//                             fixed by the evidence, so they are no label to learn from,
//                             and a world against a hard rule could not be learned from.
// Constants: Table, then O0, O1, ... in the scene file's order.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "stdlib/tabletop/scene.h"

namespace ksmc::tools::mln_tabletop {

// Throws std::runtime_error when the truth names an object the scene lacks.
std::string labelled_world_db(const stdlib::tabletop::Scene& scene, const nlohmann::json& truth,
                              const std::string& comment);

}  // namespace ksmc::tools::mln_tabletop
