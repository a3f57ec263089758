#include "stdlib/tabletop/perception/stereo/scene_from_stereo.h"

#include <algorithm>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/tabletop/perception/stereo/pose_refine.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

namespace fs = std::filesystem;

cv::Mat read_grey(const fs::path& file) {
  if (!fs::exists(file)) throw StereoError(fmt::format("{}: image not found", file.string()));
  cv::Mat img;
  try {
    img = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception&) {
    img = cv::Mat();
  }
  if (img.empty()) throw StereoError(fmt::format("{}: not a readable image", file.string()));
  return img;
}

StereoScene scene_from_images(const cv::Mat& left, const cv::Mat& right, const std::string& left_name,
                              const std::string& right_name, const StereoCalib& calib,
                              const std::vector<ObjectModel>& db, const StereoSceneOptions& options) {
  if (left.size() != right.size())
    throw StereoError(fmt::format("{}: image is {}x{} but {} is {}x{}: the stereo images differ in size", right_name,
                                  right.cols, right.rows, left_name, left.cols, left.rows));
  if (left.cols != calib.width || left.rows != calib.height)
    throw StereoError(fmt::format("{}: image is {}x{}, the calibration says {}x{}", left_name, left.cols, left.rows,
                                  calib.width, calib.height));
  StereoScene out;
  out.points = stereo_points(left, right, calib, options.stereo);
  std::vector<ObjectDetection> found = detect_objects(out.points, db, options.pose);

  Scene& s = out.scene;
  s.camera = Camera{calib.k_left(0, 0), calib.k_left(1, 1), calib.k_left(0, 2), calib.k_left(1, 2), calib.width,
                    calib.height};
  if (calib.table_in_left) {
    s.table_in_camera = *calib.table_in_left;
    s.table.size = calib.table_size;
  } else {  // the table plane through the stereo points no object claimed
    std::vector<bool> claimed(out.points.point.size(), false);
    for (const ObjectDetection& d : found)
      for (int i : d.inliers) claimed[static_cast<std::size_t>(i)] = true;
    std::vector<Eigen::Vector3d> rest;
    for (std::size_t i = 0; i < claimed.size(); ++i)
      if (!claimed[i]) rest.push_back(out.points.point[i]);
    out.table = table_from_points(rest, options.table);
    if (!out.table)
      throw StereoError(fmt::format("{}: no table: no plane holds enough of the {} unclaimed stereo points, and the "
                                    "calibration gives no table_R / table_t",
                                    left_name, rest.size()));
    s.table_in_camera = out.table->table_in_left;
    s.table.size = out.table->size;
  }
  const Pose table_from_camera = s.table_in_camera.inverse();
  auto taken = [&](const std::string& id) {
    return std::any_of(db.begin(), db.end(), [&](const ObjectModel& x) { return x.name == id; }) ||
           std::any_of(s.objects.begin(), s.objects.end(), [&](const SceneObject& x) { return x.id == id; });
  };
  for (ObjectDetection& d : found) {
    const ObjectModel& m = db[static_cast<std::size_t>(d.object)];
    if (options.refine) {
      std::vector<Eigen::Vector2d> l, r;
      for (int i : d.inliers) {
        l.push_back(out.points.left[static_cast<std::size_t>(i)]);
        r.push_back(out.points.right[static_cast<std::size_t>(i)]);
      }
      d.pose = refine_reprojection(calib, d.pose, d.model, l, r).pose;
    }
    SceneObject o;
    // A second copy is name_2, a third name_3; should the database also hold an object of
    // that name, the copy takes the next free number.
    o.id = m.name;
    if (d.instance > 0) {
      int k = d.instance + 1;
      do o.id = fmt::format("{}_{}", m.name, k++);
      while (taken(o.id));
    }
    o.model = m.name;
    o.size = m.size;
    o.pose = table_from_camera.compose(Pose::from_isometry(d.pose));
    o.keypoints_model = d.model;
    for (int i : d.inliers) o.keypoints_image.push_back(out.points.left[static_cast<std::size_t>(i)]);
    s.objects.push_back(std::move(o));
    out.detections.push_back(std::move(d));
  }
  return out;
}

StereoScene scene_from_stereo(const fs::path& left, const fs::path& right, const fs::path& calib, const fs::path& db,
                              const StereoSceneOptions& options) {
  const StereoCalib c = load_calib(calib);
  const cv::Mat l = read_grey(left), r = read_grey(right);
  const std::vector<ObjectModel> models = load_database(db, options.model);
  return scene_from_images(l, r, left.string(), right.string(), c, models, options);
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
