#include "stdlib/tabletop/overlay.h"

#include <filesystem>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "stdlib/tabletop/likelihood.h"

namespace ksmc::stdlib::tabletop {

namespace {

cv::Point to_cv(const Eigen::Vector2d& p) {
  return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
}

}  // namespace

cv::Mat render_overlay(const TabletopResult& r, std::vector<std::string>& warnings) {
  validate_result(r);
  const Scene& s = r.scene;
  cv::Mat img;
  if (!s.image.empty()) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(s.image, ec)) img = cv::imread(s.image.string(), cv::IMREAD_COLOR);
    if (img.empty())
      warnings.push_back(fmt::format("{}: cannot read background image; using a blank canvas", s.image.string()));
    else if (img.cols != s.camera.width || img.rows != s.camera.height)
      warnings.push_back(fmt::format("{}: image is {}x{}, camera is {}x{}", s.image.string(), img.cols, img.rows,
                                     s.camera.width, s.camera.height));
  }
  if (img.empty()) img = cv::Mat(s.camera.height, s.camera.width, CV_8UC3, cv::Scalar(48, 48, 48));

  const cv::Scalar red(0, 0, 255), cyan(255, 255, 0), yellow(0, 230, 255), green(0, 200, 0);
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const SceneObject& o = s.objects[i];
    const bool decided = !r.probabilities.empty();
    const auto f = decided ? decide(r.probabilities[i].false_prob) : std::nullopt;
    const auto h = decided ? decide(r.probabilities[i].hidden_prob) : std::nullopt;
    // As graph.dot: false red, hidden cyan, undecided (either P within 0.4-0.6) yellow.
    const cv::Scalar colour = (f && *f) ? red : (h && *h) ? cyan : (decided && (!f || !h)) ? yellow : green;
    const Eigen::Isometry3d cam = s.camera_pose(o).isometry();
    const Obb local = Obb::from_pose(Pose{}, o.size);
    for (int e = 0; e < 12; ++e) {
      const auto ends = local.edge(e);
      const auto a = project(s.camera, cam * ends[0]);
      const auto b = project(s.camera, cam * ends[1]);
      if (a && b) cv::line(img, to_cv(*a), to_cv(*b), colour, 2, cv::LINE_AA);
    }
    // Label above the highest projected vertex.
    std::optional<Eigen::Vector2d> top;
    for (int k = 0; k < 8; ++k) {
      const auto p = project(s.camera, cam * local.vertex(k));
      if (p && (!top || p->y() < top->y())) top = p;
    }
    if (top) {
      const cv::Point at = to_cv(*top) + cv::Point(-10, -6);
      cv::putText(img, o.id, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
      cv::putText(img, o.id, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
    }
  }
  return img;
}

}  // namespace ksmc::stdlib::tabletop
