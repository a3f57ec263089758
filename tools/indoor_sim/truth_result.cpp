#include "tools/indoor_sim/truth_result.h"

#include "stdlib/indoor/io/occupancy_map.h"

namespace ksmc::tools::indoor_sim {

using stdlib::indoor::Point2;

stdlib::indoor::io::MapInfo truth_map_info(const cv::Mat1b& image, double resolution, const std::string& source) {
  stdlib::indoor::io::MapInfo m;
  m.source = source;
  m.width = image.cols;
  m.height = image.rows;
  m.resolution = resolution;
  m.counts = stdlib::indoor::io::count_classes(
      stdlib::indoor::io::classify_image(image, stdlib::indoor::io::Thresholds{}));
  return m;
}

stdlib::indoor::io::UnitResult axis_unit(int id, const std::string& type, int x0, int y0, int x1, int y1) {
  stdlib::indoor::io::UnitResult u;
  u.id = id;
  u.type = type;
  u.type_probs[type] = 1.0;
  u.corners = {Point2{double(x0), double(y0)}, Point2{double(x1), double(y0)}, Point2{double(x1), double(y1)},
               Point2{double(x0), double(y1)}};
  return u;
}

std::array<Point2, 2> axis_door_segment(bool horizontal, int at, int from, int width) {
  const double e = from + width - 1;
  return horizontal ? std::array<Point2, 2>{Point2{double(from), double(at)}, Point2{e, double(at)}}
                    : std::array<Point2, 2>{Point2{double(at), double(from)}, Point2{double(at), e}};
}

}  // namespace ksmc::tools::indoor_sim
