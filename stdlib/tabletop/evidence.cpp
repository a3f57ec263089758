#include "stdlib/tabletop/evidence.h"

#include "stdlib/tabletop/extract_contact.h"
#include "stdlib/tabletop/extract_higher.h"
#include "stdlib/tabletop/extract_hover.h"
#include "stdlib/tabletop/extract_intersect.h"
#include "stdlib/tabletop/extract_stable.h"

namespace ksmc::stdlib::tabletop {

namespace {

void compute_pair(Evidence& ev, std::size_t a, std::size_t b, const EvidenceParams& params) {
  const PairGeometry g = pair_geometry(ev.boxes[a], ev.boxes[b], params.max_contact_eps());
  PairGeometry g_ba = g;
  g_ba.direction = -g.direction;
  ev.geometry[a][b] = g;
  ev.geometry[b][a] = g_ba;
  const char inter = intersect_from_geometry(g, params) ? 1 : 0;
  const char cont = contact_from_geometry(g, params) ? 1 : 0;
  ev.intersect[a][b] = ev.intersect[b][a] = inter;
  ev.contact[a][b] = ev.contact[b][a] = cont;
  ev.higher[a][b] = extract_higher(ev.boxes[a], ev.boxes[b], params) ? 1 : 0;
  ev.higher[b][a] = extract_higher(ev.boxes[b], ev.boxes[a], params) ? 1 : 0;
}

void compute_hover(Evidence& ev) {
  for (std::size_t i = 0; i < ev.size(); ++i)
    ev.hover[i] = ev.is_table[i] ? 0 : (extract_hover(i, ev.contact, ev.intersect) ? 1 : 0);
}

}  // namespace

Evidence extract_evidence(const Scene& scene, const EvidenceParams& params) {
  Evidence ev;
  const std::size_t n = scene.objects.size() + 1;
  ev.ids.reserve(n);
  ev.ids.emplace_back(kTableId);
  ev.boxes.push_back(scene.table.obb());
  for (const auto& o : scene.objects) {
    ev.ids.push_back(o.id);
    ev.boxes.push_back(o.obb());
  }
  ev.stable.assign(n, 0);
  ev.hover.assign(n, 0);
  ev.is_table.assign(n, 0);
  ev.is_table[0] = 1;
  ev.stable[0] = 1;  // r9: the table is stable
  for (std::size_t i = 1; i < n; ++i) ev.stable[i] = extract_stable(ev.boxes[i], params) ? 1 : 0;
  ev.contact.assign(n, std::vector<char>(n, 0));
  ev.intersect.assign(n, std::vector<char>(n, 0));
  ev.higher.assign(n, std::vector<char>(n, 0));
  ev.geometry.assign(n, std::vector<PairGeometry>(n));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) compute_pair(ev, a, b, params);
  compute_hover(ev);
  return ev;
}

void update_evidence(Evidence& ev, const Scene& scene, std::size_t object_index, const EvidenceParams& params) {
  const std::size_t k = Evidence::body(object_index);
  ev.boxes[k] = scene.objects[object_index].obb();
  ev.stable[k] = extract_stable(ev.boxes[k], params) ? 1 : 0;
  for (std::size_t j = 0; j < ev.size(); ++j)
    if (j != k) compute_pair(ev, k, j, params);
  compute_hover(ev);
}

}  // namespace ksmc::stdlib::tabletop
