#include "stdlib/tabletop/perception/stereo/stereo_calib.h"

#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <opencv2/core.hpp>
#include <opencv2/core/eigen.hpp>

#include "stdlib/tabletop/perception/stereo/object_db.h"

namespace ksmc::stdlib::tabletop::perception::stereo {

namespace fs = std::filesystem;

Eigen::Matrix3d StereoCalib::fundamental() const {
  Eigen::Matrix3d tx;
  tx << 0, -t.z(), t.y(), t.z(), 0, -t.x(), -t.y(), t.x(), 0;
  return k_right.inverse().transpose() * tx * r * k_left.inverse();
}

namespace {

template <int R, int C>
Eigen::Matrix<double, R, C> read_matrix(const cv::FileStorage& fs, const char* key, const fs::path& file) {
  const cv::FileNode node = fs[key];
  if (node.empty()) throw StereoError(fmt::format("{}: {}: missing", file.string(), key));
  cv::Mat m;
  try {
    node >> m;
  } catch (const cv::Exception&) {
    m = cv::Mat();
  }
  if (m.empty() && node.isSeq() && node.size() == static_cast<std::size_t>(R * C)) {  // plain list
    std::vector<double> v;
    node >> v;
    m = cv::Mat(v, true).reshape(1, R);
  }
  if (m.rows != R || m.cols != C)
    throw StereoError(fmt::format("{}: {}: expected a {}x{} matrix", file.string(), key, R, C));
  m.convertTo(m, CV_64F);
  Eigen::Matrix<double, R, C> e;
  cv::cv2eigen(m, e);
  if (!e.allFinite()) throw StereoError(fmt::format("{}: {}: not finite", file.string(), key));
  return e;
}

void check_rotation(const Eigen::Matrix3d& r, const char* key, const fs::path& file) {
  if ((r * r.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-4 || r.determinant() < 0.0)
    throw StereoError(fmt::format("{}: {}: not a rotation matrix", file.string(), key));
}

void check_intrinsics(const Eigen::Matrix3d& k, const char* key, const fs::path& file) {
  if (!(k(0, 0) > 0.0 && k(1, 1) > 0.0) || std::abs(k(2, 2) - 1.0) > 1e-9 || k(2, 0) != 0.0 || k(2, 1) != 0.0)
    throw StereoError(fmt::format("{}: {}: not a camera matrix [fx 0 cx; 0 fy cy; 0 0 1]", file.string(), key));
}

}  // namespace

StereoCalib load_calib(const fs::path& file) {
  if (!fs::exists(file)) throw StereoError(fmt::format("{}: calibration file not found", file.string()));
  cv::FileStorage fs;
  try {
    fs.open(file.string(), cv::FileStorage::READ | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw StereoError(fmt::format("{}: not a readable YAML calibration ({})", file.string(), e.err));
  }
  if (!fs.isOpened()) throw StereoError(fmt::format("{}: not a readable YAML calibration", file.string()));
  StereoCalib c;
  const cv::FileNode w = fs["image_width"], h = fs["image_height"];
  if (w.empty() || h.empty() || !w.isInt() || !h.isInt())
    throw StereoError(fmt::format("{}: image_width / image_height: missing or not integers", file.string()));
  c.width = static_cast<int>(w);
  c.height = static_cast<int>(h);
  if (c.width <= 0 || c.height <= 0) throw StereoError(fmt::format("{}: image size must be positive", file.string()));
  c.k_left = read_matrix<3, 3>(fs, "K_left", file);
  c.k_right = read_matrix<3, 3>(fs, "K_right", file);
  check_intrinsics(c.k_left, "K_left", file);
  check_intrinsics(c.k_right, "K_right", file);
  c.r = read_matrix<3, 3>(fs, "R", file);
  check_rotation(c.r, "R", file);
  c.t = read_matrix<3, 1>(fs, "t", file);
  if (c.t.norm() < 1e-4) throw StereoError(fmt::format("{}: t: zero baseline", file.string()));
  if (fs["table_R"].empty() != fs["table_t"].empty())
    throw StereoError(fmt::format("{}: table_R and table_t: give both or neither", file.string()));
  if (!fs["table_R"].empty()) {
    const Eigen::Matrix3d tr = read_matrix<3, 3>(fs, "table_R", file);
    check_rotation(tr, "table_R", file);
    Pose table;
    table.q = Eigen::Quaterniond(tr).normalized();
    table.t = read_matrix<3, 1>(fs, "table_t", file);
    c.table_in_left = table;
  }
  if (!fs["table_size"].empty()) c.table_size = read_matrix<3, 1>(fs, "table_size", file);
  return c;
}

void save_calib(const fs::path& file, const StereoCalib& c) {
  cv::FileStorage fs(file.string(), cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
  if (!fs.isOpened()) throw StereoError(fmt::format("{}: cannot write", file.string()));
  cv::Mat m;
  fs << "image_width" << c.width << "image_height" << c.height;
  cv::eigen2cv(c.k_left, m);
  fs << "K_left" << m;
  cv::eigen2cv(c.k_right, m);
  fs << "K_right" << m;
  cv::eigen2cv(c.r, m);
  fs << "R" << m;
  cv::eigen2cv(c.t, m);
  fs << "t" << m;
  if (c.table_in_left) {
    const Eigen::Matrix3d tr = c.table_in_left->rotation();
    cv::eigen2cv(tr, m);
    fs << "table_R" << m;
    cv::eigen2cv(c.table_in_left->t, m);
    fs << "table_t" << m;
  }
  cv::eigen2cv(c.table_size, m);
  fs << "table_size" << m;
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
