#include "stdlib/tabletop/perception/cluster_boxes.h"

#include <deque>

namespace ksmc::stdlib::tabletop::perception {

std::vector<UprightBox> fit_cluster_boxes(const Points& points, const ClusterBoxOptions& o, const RayIndex* rays) {
  std::vector<UprightBox> out;
  std::deque<Points> todo{points};
  int tilted = 0;
  while (!todo.empty()) {
    Points part = std::move(todo.front());
    todo.pop_front();
    if (o.tilted && tilted < o.max_tilted) {
      if (std::optional<TiltedFit> t = fit_tilted_box(part, o.tilt)) {
        ++tilted;
        out.push_back(t->box);
        ClusterOptions c = o.parts;
        c.min_height = -1e9;
        c.max_height = 1e9;
        const Eigen::Vector2d everywhere(1e9, 1e9);
        // Joined along grazing tops' rows as the cloud was, where the sensor is known.
        const AboveTable rest(t->rest, everywhere, c);
        for (Points& part : rays != nullptr ? rest.clusters(c, rays->free_space().sensor) : rest.clusters(c))
          todo.push_back(std::move(part));
        continue;
      }
    }
    if (o.split_stacks) {
      for (const UprightBox& b : fit_stacked_boxes(part, o.box, o.stacks, rays)) out.push_back(b);
    } else {
      out.push_back(fit_upright_box(part, o.box));
    }
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception
