#include "runtime/report/folder_data.h"

#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>

#include "runtime/report/data_uri.h"
#include "runtime/report/trace_columns.h"

namespace ksmc::runtime::report {

namespace {

std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for the report");
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::optional<nlohmann::json> read_json(const std::filesystem::path& path) {
  const auto text = read_text(path);
  if (!text) return std::nullopt;
  try {
    return nlohmann::json::parse(*text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

// The table-top input scene (camera intrinsics, table pose, box sizes): what the page needs
// to draw the boxes; scene_graph.json has only the poses. Best effort: the path in
// summary.json is as given on the command line, so it may not resolve from elsewhere.
std::optional<nlohmann::json> scene_input(const nlohmann::json& summary) {
  if (!summary.contains("inputs") || !summary["inputs"].is_array() || summary["inputs"].empty()) return std::nullopt;
  const auto& first = summary["inputs"][0];
  if (!first.contains("path") || !first["path"].is_string()) return std::nullopt;
  std::optional<nlohmann::json> scene;
  try {
    scene = read_json(first["path"].get<std::string>());
  } catch (const std::exception&) {
    return std::nullopt;  // not JSON: not a scene this page can use
  }
  if (!scene || !scene->is_object() || !scene->contains("objects") || !(*scene)["objects"].is_array()) return std::nullopt;
  nlohmann::json out = nlohmann::json::object();
  for (const char* key : {"camera", "table"})
    if (scene->contains(key)) out[key] = (*scene)[key];
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& o : (*scene)["objects"]) {
    if (!o.is_object()) continue;
    nlohmann::json slim = nlohmann::json::object();
    for (const char* key : {"id", "model", "size"})
      if (o.contains(key)) slim[key] = o[key];
    objects.push_back(std::move(slim));
  }
  out["objects"] = std::move(objects);
  return out;
}

}  // namespace

nlohmann::json collect_run_data(const std::filesystem::path& dir, const nlohmann::json& summary,
                                const FolderLimits& limits) {
  nlohmann::json data = nlohmann::json::object();
  data["folder"] = dir.filename().empty() ? dir.parent_path().filename().string() : dir.filename().string();
  data["summary"] = summary;
  data["kind"] = "run";
  if (auto world = read_json(dir / "world.json")) {
    data["world"] = std::move(*world);
    data["kind"] = "indoor";
  }
  if (auto graph = read_json(dir / "scene_graph.json")) {
    data["scene_graph"] = std::move(*graph);
    data["kind"] = "tabletop";
    if (auto scene = scene_input(summary)) data["scene_input"] = std::move(*scene);
  }
  if (auto segs = read_json(dir / "segments.json")) {
    data["segments"] = std::move(*segs);
    data["kind"] = "segments";
  }
  if (const auto csv = read_text(dir / "trace.csv")) {
    try {
      data["trace"] = trace_columns(*csv, limits.max_trace_rows);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error((dir / e.what()).string());  // "DIR/trace.csv:3: ..."
    }
  }
  nlohmann::json images = nlohmann::json::object();
  if (auto uri = file_data_uri(dir / "overlay.png", "image/png", limits.max_image_bytes)) images["overlay"] = std::move(*uri);
  if (auto uri = file_data_uri(dir / "graph.png", "image/png", limits.max_image_bytes)) images["graph"] = std::move(*uri);
  data["images"] = std::move(images);
  return data;
}

}  // namespace ksmc::runtime::report
