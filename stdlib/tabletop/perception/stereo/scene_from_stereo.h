// The stereo front end (issue 13, part 4; seed Alg. 2): a stereo pair, its calibration and
// an object database -> the stdlib/tabletop Scene the kit consumes: camera = the left
// camera, the table from the calibration or else fitted to the stereo points
// (stereo_table.h), one object per database object found (id and model
// = its folder name, the database box size, the estimated pose) with its inlier keypoints
// (left pixel + model point) for the reprojection likelihood (eq. 4.4).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "stdlib/tabletop/perception/stereo/object_pose.h"
#include "stdlib/tabletop/perception/stereo/stereo_points.h"
#include "stdlib/tabletop/perception/stereo/stereo_table.h"
#include "stdlib/tabletop/scene.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

struct StereoSceneOptions {
  StereoOptions stereo;
  PoseOptions pose;
  ModelOptions model;
  TableOptions table;
  bool refine = true;  // reprojection refinement of each pose (pose_refine.h)
};

struct StereoScene {
  Scene scene;
  StereoPoints points;
  std::vector<ObjectDetection> detections;  // same order as scene.objects
  std::optional<StereoTable> table;         // when fitted (no table in the calibration)
};

// Reads an 8-bit image as grey; StereoError naming the file when unreadable.
cv::Mat read_grey(const std::filesystem::path& file);

// In-memory pipeline. The images must both have the calibration's size: otherwise a
// StereoError naming `left_name` / `right_name`.
StereoScene scene_from_images(const cv::Mat& left, const cv::Mat& right, const std::string& left_name,
                              const std::string& right_name, const StereoCalib& calib,
                              const std::vector<ObjectModel>& db, const StereoSceneOptions& options = {});

// Files: images, stereo.yaml, database folder. Every error is a StereoError naming its file.
StereoScene scene_from_stereo(const std::filesystem::path& left, const std::filesystem::path& right,
                              const std::filesystem::path& calib, const std::filesystem::path& db,
                              const StereoSceneOptions& options = {});

}  // namespace ksmc::stdlib::tabletop::perception::stereo
