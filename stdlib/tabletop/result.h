// Table-top inference result and the scene graph read from it (seed §4.10):
// per-object query probabilities with 0.4 / 0.6 decisions, stable support edges
// (rule r10: stable(a) ∧ stable(b) ∧ contact(a,b) ∧ higher(a,b)) and the remaining,
// unstable contacts.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "stdlib/tabletop/evidence.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop {

struct ObjectProbabilities {
  double false_prob = 0.0;   // P(false(o) | evidence)
  double hidden_prob = 0.0;  // P(hidden(o) | evidence)
};

// Input of the writers.
struct TabletopResult {
  Scene scene;
  // One per scene.objects entry, same order; empty when the domain declares no decisions
  // output (then the writers report relations only).
  std::vector<ObjectProbabilities> probabilities;
  Evidence evidence;                               // extract_evidence(scene, ...)
};

// Seed §4.10.1: true above 0.6, false below 0.4, no decision (nullopt) in between.
std::optional<bool> decide(double probability);

using Edge = std::pair<std::string, std::string>;
// [upper, lower] pairs of stable support, sorted by (upper, lower).
std::vector<Edge> support_edges(const Evidence& ev);
// Contacts that are not stable support, each unordered pair once as [min, max] by id, sorted.
std::vector<Edge> unstable_contact_edges(const Evidence& ev);
// Pairs of objects whose boxes cut into each other (intersect), each unordered pair once as
// [min, max] by id, sorted; false estimates included: the conflicts a decision rests on, and
// where two estimates are left undecided, the pair one of which is wrong.
std::vector<Edge> intersect_edges(const Evidence& ev);
// The scene graph's edges: those of the evidence between bodies that are not decided false
// (false_prob above 0.6). A false estimate is no body: it neither carries, nor rests on, nor
// touches anything. Undecided objects keep their edges; without probabilities all are kept.
std::vector<Edge> support_edges(const TabletopResult& result);
std::vector<Edge> unstable_contact_edges(const TabletopResult& result);

// Throws std::invalid_argument when probabilities / evidence do not match the scene.
void validate_result(const TabletopResult& result);

// {"objects":[{"id","pose","stable","false_prob","hidden_prob","false","hidden"}],
//  "support":[[upper,lower]],"contact":[[a,b]],"intersect":[[a,b]]} (support and contact: the
// result's edges, none of an object decided false; intersect: every pair of boxes that cut
// each other, false estimates included); "pose" is in the camera frame
// ({"t":[x,y,z],"q":[w,x,y,z]}, as in scene.json). Without probabilities the four
// probability / decision keys are left out. Object ids are echoed in the JSON type scene.json
// gave them (string or number), in the objects and in the edges.
nlohmann::json scene_graph_json(const TabletopResult& result);
// The JSON value of a body id: a number when scene.json gave the object a numeric id.
nlohmann::json id_json(const Scene& scene, const std::string& id);
}  // namespace ksmc::stdlib::tabletop
