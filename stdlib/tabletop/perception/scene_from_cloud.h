// The point-cloud front end (issue 13, part 1): cloud file -> table frame -> point spacing
// -> clusters -> one upright box per cluster -> the stdlib/tabletop Scene the kit consumes,
// plus the per-object points the cloud likelihood needs. The cloud frame is taken as the camera
// frame (Scene::table_in_camera = the table frame in the cloud frame).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "stdlib/tabletop/perception/box_fit.h"
#include "stdlib/tabletop/perception/cloud_io.h"
#include "stdlib/tabletop/perception/cluster_boxes.h"
#include "stdlib/tabletop/perception/clusters.h"
#include "stdlib/tabletop/perception/face_strip.h"
#include "stdlib/tabletop/perception/hidden_bottom.h"
#include "stdlib/tabletop/perception/hidden_reach.h"
#include "stdlib/tabletop/perception/lean_seat.h"
#include "stdlib/tabletop/perception/occluded_gap.h"
#include "stdlib/tabletop/perception/seen_under.h"
#include "stdlib/tabletop/perception/shadow_merge.h"
#include "stdlib/tabletop/perception/stack_split.h"
#include "stdlib/tabletop/perception/table_plane.h"
#include "stdlib/tabletop/perception/tilted_foot.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::perception {

struct CloudOptions {
  Units units = Units::m;
  TableOptions table;
  // clusters.tolerance is a floor: a sparser cloud gets spacing_factor x its object point
  // spacing, and the box fits' radii, cells and point counts follow (sampling-dependent
  // settings scaled by derived / floor tolerance); spacing_factor = 0 keeps everything fixed.
  ClusterOptions clusters;
  ShadowMergeOptions shadow;  // clusters split by a resting box's shadow joined (shadow_merge.h)
  ClusterBoxOptions fit;     // boxes per cluster: tilted, stacked, upright (cluster_boxes.h)
  SeenUnderOptions seen_under;        // boxes from the table the sensor saw under are cut (seen_under.h)
  HiddenBottomOptions hidden_bottom;  // boxes whose foot is hidden grow down to the table (hidden_bottom.h)
  HiddenReachOptions hidden_reach;    // a box under one that overhangs it grows where it is hidden (hidden_reach.h)
  TiltedFootOptions tilted_foot;      // a tilted box whose foot is hidden grows down to the table (tilted_foot.h)
  OccludedGapOptions occluded_gap;    // the two ends of a box something lies across are one (occluded_gap.h)
  FaceStripOptions face_strip;        // a thin box on a larger one is a strip of its face: dropped (face_strip.h)
  LeanSeatOptions lean_seat;          // a tilted box cutting into an upright one is cut back where unseen (lean_seat.h)
  Camera camera{615.0, 615.0, 320.0, 240.0, 640, 480};  // written to scene.json (overlay)
  double table_thickness = 0.05;                        // m, the slab below z = 0
  std::string id_prefix = "obj_";
  // Called as each phase starts, with its name (the run's progress lines of large clouds,
  // runtime/cli/stage_log.h); may be empty.
  std::function<void(std::string_view)> stage;
};

struct CloudScene {
  Scene scene;                         // objects in the table frame, ids <prefix>0..
  TableFit table;
  std::vector<Points> object_points;   // table frame, the points of each scene object's box
  std::vector<int> cluster_of;         // per scene object: its cluster (stacked boxes share one)
  std::size_t cloud_points = 0;
  Points cloud_in_table;               // the whole cloud in the table frame
  Eigen::Vector3d sensor_in_table = Eigen::Vector3d::Zero();  // the cloud origin
  double point_spacing = 0.0;      // m, object_point_spacing (0 when not derived)
  double cluster_tolerance = 0.0;  // m, the clustering tolerance used
};

// The clusters mapped back into the cloud frame.
std::vector<Points> clusters_in_cloud(const CloudScene& cs);

// Throws CloudError naming `path` (unreadable, empty, NaN, no plane, no object above it).
CloudScene scene_from_cloud(const std::filesystem::path& path, const CloudOptions& options = {});
// Same on points already in memory (metres); `source` names them in errors.
CloudScene scene_from_points(const Points& cloud, const std::string& source, const CloudOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception
