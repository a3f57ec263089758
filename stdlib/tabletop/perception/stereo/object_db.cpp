#include "stdlib/tabletop/perception/stereo/object_db.h"

#include <algorithm>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ksmc::stdlib::tabletop::perception::stereo {

namespace fs = std::filesystem;

FaceFrame face_frame(int face) {
  FaceFrame f;
  f.normal = face / 2;
  f.sign = face % 2 == 0 ? 1.0 : -1.0;
  const int a = (f.normal + 1) % 3, b = (f.normal + 2) % 3;  // e_a x e_b = e_normal
  if (f.sign > 0) {
    f.u_axis = b;
    f.v_axis = a;
  } else {
    f.u_axis = a;
    f.v_axis = b;
  }
  return f;
}

Eigen::Vector3d face_point(int face, const Eigen::Vector3d& size, double x, double y, int w, int h) {
  const FaceFrame f = face_frame(face);
  Eigen::Vector3d p;
  p[f.normal] = 0.5 * f.sign * size[f.normal];
  p[f.u_axis] = ((x + 0.5) / w - 0.5) * size[f.u_axis];
  p[f.v_axis] = ((y + 0.5) / h - 0.5) * size[f.v_axis];
  return p;
}

namespace {

Eigen::Vector3d read_size(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw StereoError(fmt::format("{}: cannot read the object description", file.string()));
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw StereoError(fmt::format("{}: not valid JSON ({})", file.string(), e.what()));
  }
  const auto it = doc.find("size");
  if (it == doc.end() || !it->is_array() || it->size() != 3)
    throw StereoError(fmt::format("{}: size: expected [x, y, z] in metres", file.string()));
  Eigen::Vector3d s;
  for (int k = 0; k < 3; ++k) {
    if (!(*it)[k].is_number()) throw StereoError(fmt::format("{}: size[{}]: not a number", file.string(), k));
    s[k] = (*it)[k].get<double>();
    if (!(s[k] > 0.0 && s[k] < 10.0))
      throw StereoError(fmt::format("{}: size[{}]: {} is not a box extent in metres", file.string(), k, s[k]));
  }
  return s;
}

}  // namespace

ObjectModel build_model(const fs::path& folder, const ModelOptions& options) {
  ObjectModel m;
  m.folder = folder;
  m.name = folder.filename().string();
  m.size = read_size(folder / "object.json");
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create(options.max_features_per_face, 3, options.contrast_threshold);
  int textures = 0;
  for (int f = 0; f < 6; ++f) {
    const fs::path file = folder / fmt::format("face_{}.png", kFaceNames[f]);
    if (!fs::exists(file)) continue;
    const cv::Mat img = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
    if (img.empty()) throw StereoError(fmt::format("{}: not a readable image", file.string()));
    ++textures;
    for (const double scale : options.scales) {
      cv::Mat level = img;
      if (scale != 1.0) cv::resize(img, level, cv::Size(), scale, scale, cv::INTER_AREA);
      if (level.cols < 16 || level.rows < 16) continue;
      std::vector<cv::KeyPoint> kps;
      cv::Mat desc;
      sift->detectAndCompute(level, cv::noArray(), kps, desc);
      for (std::size_t i = 0; i < kps.size(); ++i) {
        m.points.push_back(face_point(f, m.size, kps[i].pt.x, kps[i].pt.y, level.cols, level.rows));
        m.faces.push_back(f);
        m.descriptors.push_back(desc.row(static_cast<int>(i)));
      }
    }
  }
  if (textures == 0)
    throw StereoError(fmt::format("{}: no face texture (face_px.png ... face_nz.png)", folder.string()));
  if (m.points.empty())
    throw StereoError(fmt::format("{}: no SIFT features on any of its {} face textures", folder.string(), textures));
  return m;
}

void save_model(const fs::path& file, const ObjectModel& model) {
  cv::FileStorage fs(file.string(), cv::FileStorage::WRITE);
  if (!fs.isOpened()) throw StereoError(fmt::format("{}: cannot write", file.string()));
  fs << "name" << model.name;
  fs << "size" << std::vector<double>{model.size.x(), model.size.y(), model.size.z()};
  cv::Mat pts(static_cast<int>(model.points.size()), 3, CV_64F);
  for (int i = 0; i < pts.rows; ++i)
    for (int k = 0; k < 3; ++k) pts.at<double>(i, k) = model.points[static_cast<std::size_t>(i)][k];
  fs << "points" << pts << "faces" << model.faces << "descriptors" << model.descriptors;
}

ObjectModel load_model(const fs::path& file) {
  cv::FileStorage fs;
  try {
    fs.open(file.string(), cv::FileStorage::READ);
  } catch (const cv::Exception&) {
    throw StereoError(fmt::format("{}: not a readable model file", file.string()));
  }
  if (!fs.isOpened()) throw StereoError(fmt::format("{}: not a readable model file", file.string()));
  ObjectModel m;
  m.folder = file.parent_path();
  std::vector<double> size;
  cv::Mat pts;
  fs["name"] >> m.name;
  fs["size"] >> size;
  fs["points"] >> pts;
  fs["faces"] >> m.faces;
  fs["descriptors"] >> m.descriptors;
  if (size.size() != 3 || pts.cols != 3 || pts.type() != CV_64F || m.descriptors.rows != pts.rows ||
      m.descriptors.cols != 128 || m.descriptors.type() != CV_32F || static_cast<int>(m.faces.size()) != pts.rows)
    throw StereoError(fmt::format("{}: malformed model (expected name, size[3], points Nx3, faces N, descriptors Nx128)",
                                  file.string()));
  if (pts.rows == 0) throw StereoError(fmt::format("{}: the model has no features", file.string()));
  m.size = Eigen::Vector3d(size[0], size[1], size[2]);
  for (int i = 0; i < pts.rows; ++i) m.points.emplace_back(pts.at<double>(i, 0), pts.at<double>(i, 1), pts.at<double>(i, 2));
  return m;
}

std::vector<ObjectModel> load_database(const fs::path& dir, const ModelOptions& options) {
  if (!fs::is_directory(dir)) throw StereoError(fmt::format("{}: not a database folder", dir.string()));
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_directory() && fs::exists(e.path() / "object.json")) folders.push_back(e.path());
  std::sort(folders.begin(), folders.end());
  if (folders.empty()) throw StereoError(fmt::format("{}: no object folder (a folder with object.json)", dir.string()));
  std::vector<ObjectModel> out;
  for (const fs::path& f : folders) {
    const fs::path model = f / "model.yml";
    out.push_back(fs::exists(model) ? load_model(model) : build_model(f, options));
    out.back().name = f.filename().string();
    out.back().folder = f;
  }
  return out;
}

}  // namespace ksmc::stdlib::tabletop::perception::stereo
