// Table-top scene in the table frame: camera, table slab, objects with their OBB
// and matched keypoints. Built from scene.json (scene_io.h) or other importers.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stdlib/tabletop/obb.h"
#include "stdlib/tabletop/pose.h"

namespace ksmc::stdlib::tabletop {

struct CloudObservation;  // cloud_likelihood.h

inline constexpr const char* kTableId = "table";

struct Camera {
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  int width = 0, height = 0;
};

struct SceneObject {
  std::string id;
  bool numeric_id = false;  // scene.json gave the id as a number (`id` is its JSON text); echoed as one
  std::string model;
  Eigen::Vector3d size = Eigen::Vector3d::Zero();  // full OBB extents [m]
  Pose pose;                                       // OBB centre + orientation, TABLE frame
  std::vector<Eigen::Vector3d> keypoints_model;    // object (OBB) frame [m]
  std::vector<Eigen::Vector2d> keypoints_image;    // pixels, same length as keypoints_model

  [[nodiscard]] Obb obb() const { return Obb::from_pose(pose, size); }
};

// The table as a constant: a thin slab right below z = 0 of the table frame.
struct TableSlab {
  Eigen::Vector3d size{2.0, 2.0, 0.05};  // x, y extent and thickness [m]
  [[nodiscard]] Obb obb() const {
    Obb b;
    b.center = Eigen::Vector3d(0.0, 0.0, -0.5 * size.z());
    b.axes = Eigen::Matrix3d::Identity();
    b.half = 0.5 * size;
    return b;
  }
};

struct Scene {
  Camera camera;
  Pose table_in_camera;             // table frame expressed in the camera frame
  TableSlab table;
  std::filesystem::path image;      // optional background image (absolute or cwd-relative), may be empty
  std::vector<SceneObject> objects; // file order; ids unique, never "table"
  // One standard deviation [m] of the depth noise of the sensor data the poses were read
  // from (the --cloud front end: its table plane's RMS residual); 0 when not known. When
  // known, the near-vertical tolerances come from it rather than from the poses' resting
  // gaps (gap_noise.h), which a front end that seats its boxes makes exactly 0.
  double depth_noise = 0.0;
  // What the --cloud front end saw (each object's points, the cloud's rays), for the
  // `cloud.surface` likelihood; null for a scene read from scene.json.
  std::shared_ptr<const CloudObservation> cloud;

  // Object pose in the camera frame.
  [[nodiscard]] Pose camera_pose(const SceneObject& o) const { return table_in_camera.compose(o.pose); }
  // Index of the object with this id, or -1.
  [[nodiscard]] int find(const std::string& id) const {
    for (std::size_t i = 0; i < objects.size(); ++i)
      if (objects[i].id == id) return static_cast<int>(i);
    return -1;
  }
};

}  // namespace ksmc::stdlib::tabletop
