// runtime/report: base64, trace.csv columns, the inline-data escaping and the page built
// from a run folder (which files select which drawing).
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "runtime/report/data_uri.h"
#include "runtime/report/folder_data.h"
#include "runtime/report/page.h"
#include "runtime/report/trace_columns.h"

namespace rep = ksmc::runtime::report;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / ("ksmc_report_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  void put(const std::string& file, const std::string& text) const { std::ofstream(path / file, std::ios::binary) << text; }
};

const nlohmann::json kSummary = {{"domain", {{"name", "indoor"}, {"version", "1.0"}}}, {"seed", 1}, {"inputs", nlohmann::json::array()}};

}  // namespace

TEST_CASE("base64 matches RFC 4648 test vectors", "[report]") {
  CHECK(rep::base64("") == "");
  CHECK(rep::base64("f") == "Zg==");
  CHECK(rep::base64("fo") == "Zm8=");
  CHECK(rep::base64("foo") == "Zm9v");
  CHECK(rep::base64("foob") == "Zm9vYg==");
  CHECK(rep::base64("fooba") == "Zm9vYmE=");
  CHECK(rep::base64("foobar") == "Zm9vYmFy");
  CHECK(rep::base64(std::string("\xff\x00\x80", 3)) == "/wCA");
}

TEST_CASE("file_data_uri embeds small files and skips absent or large ones", "[report]") {
  TempDir d("uri");
  d.put("a.png", "foo");
  CHECK(rep::file_data_uri(d.path / "a.png", "image/png", 100) == std::optional<std::string>("data:image/png;base64,Zm9v"));
  CHECK_FALSE(rep::file_data_uri(d.path / "a.png", "image/png", 2).has_value());
  CHECK_FALSE(rep::file_data_uri(d.path / "missing.png", "image/png", 100).has_value());
}

TEST_CASE("trace_columns splits trace.csv by chain, empty cells are null", "[report]") {
  const std::string csv =
      "chain,iteration,log_posterior,acceptance_window,acceptance_ADD,acceptance_REMOVE\n"
      "0,10,-5.5,0.5,1,\n"
      "1,10,-6,0.25,0,0.5\n"
      "0,20,-4,0.75,,0.25\n"
      "1,20,-inf,0,0,0\n";
  const auto t = rep::trace_columns(csv);
  REQUIRE(t["columns"] == nlohmann::json({"iteration", "log_posterior", "acceptance_window", "acceptance_ADD", "acceptance_REMOVE"}));
  REQUIRE(t["chains"].size() == 2);
  CHECK(t["chains"][0]["chain"] == 0);
  CHECK(t["chains"][0]["iteration"] == nlohmann::json({10.0, 20.0}));
  CHECK(t["chains"][0]["acceptance_ADD"] == nlohmann::json({1.0, nullptr}));
  CHECK(t["chains"][0]["acceptance_REMOVE"] == nlohmann::json({nullptr, 0.25}));
  CHECK(t["chains"][1]["log_posterior"] == nlohmann::json({-6.0, nullptr}));  // -inf: no JSON number
}

TEST_CASE("trace_columns thins long chains evenly and keeps both ends", "[report]") {
  std::string csv = "chain,iteration,log_posterior\n";
  for (int i = 0; i <= 100; ++i) csv += "0," + std::to_string(i) + ",0\n";
  const auto t = rep::trace_columns(csv, 11);
  const auto& it = t["chains"][0]["iteration"];
  REQUIRE(it.size() == 11);
  CHECK(it.front() == 0.0);
  CHECK(it[5] == 50.0);
  CHECK(it.back() == 100.0);
}

TEST_CASE("trace_columns names the line of a malformed row", "[report]") {
  CHECK_THROWS_WITH(rep::trace_columns("chain,iteration\n0,1\n0,1,2\n"), Catch::Contains("trace.csv:3:"));
  CHECK_THROWS_WITH(rep::trace_columns("chain,iteration\n0,x\n"), Catch::Contains("trace.csv:2: 'x' is not a number"));
  CHECK_THROWS_WITH(rep::trace_columns("iteration\n1\n"), Catch::Contains("trace.csv:1:"));
}

TEST_CASE("script_safe_json cannot close the data script element", "[report]") {
  const nlohmann::json j = {{"name", "</script><script>alert(1)</script>"}};
  const std::string s = rep::script_safe_json(j);
  CHECK(s.find("</") == std::string::npos);
  CHECK(nlohmann::json::parse(s) == j);  // "<\/" is a valid JSON escape of "</"
}

TEST_CASE("the folder's files select the drawing", "[report]") {
  TempDir d("kind");
  CHECK(rep::collect_run_data(d.path, kSummary)["kind"] == "run");
  d.put("world.json", R"({"map":{"width":4,"height":3,"resolution":0.05},"units":[],"doors":[],"adjacent":[],"metrics":{}})");
  d.put("trace.csv", "chain,iteration,log_posterior\n0,1,-3\n");
  const auto data = rep::collect_run_data(d.path, kSummary);
  CHECK(data["kind"] == "indoor");
  CHECK(data["world"]["map"]["width"] == 4);
  CHECK(data["trace"]["chains"][0]["log_posterior"] == nlohmann::json({-3.0}));
  CHECK(data["images"].empty());
  d.put("world.json", "{ not json");
  CHECK_THROWS_WITH(rep::collect_run_data(d.path, kSummary), Catch::Contains("world.json: not valid JSON"));
}

TEST_CASE("the table-top page carries the input scene's sizes and camera, not its key points", "[report]") {
  TempDir d("tabletop");
  d.put("scene.json", R"({"camera":{"fx":600,"fy":600,"cx":320,"cy":240},"objects":[{"id":"a","size":[1,2,3],"keypoints":{"model":[]}}]})");
  d.put("scene_graph.json", R"({"objects":[],"support":[],"contact":[]})");
  nlohmann::json summary = kSummary;
  summary["inputs"] = {{{"path", (d.path / "scene.json").string()}}};
  const auto data = rep::collect_run_data(d.path, summary);
  CHECK(data["kind"] == "tabletop");
  CHECK(data["scene_input"]["camera"]["fx"] == 600);
  CHECK(data["scene_input"]["objects"][0] == nlohmann::json({{"id", "a"}, {"size", {1, 2, 3}}}));
  summary["inputs"] = {{{"path", (d.path / "gone.json").string()}}};
  CHECK_FALSE(rep::collect_run_data(d.path, summary).contains("scene_input"));
}

TEST_CASE("render_page fills every marker once and keeps marker-like text in the data", "[report]") {
  TempDir d("@DATA@");
  d.put("segments.json", R"({"segments":[{"id":1,"a":[0,0],"b":[1,0],"length":1,"support":3,"probabilities":{}}],"relations":{},"metrics":{}})");
  const std::string html = rep::report_html(d.path, kSummary);
  CHECK(html.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(html.find("<title>ksmc indoor report: ksmc_report_@DATA@</title>") != std::string::npos);
  CHECK(html.find("@STYLE@") == std::string::npos);
  CHECK(html.find("@SCRIPTS@") == std::string::npos);
  CHECK(html.find("K.drawSegments = function") != std::string::npos);
  const auto begin = html.find("<script type=\"application/json\" id=\"ksmc-data\">");
  REQUIRE(begin != std::string::npos);
  const auto start = html.find('>', begin) + 1;
  const auto data = nlohmann::json::parse(html.substr(start, html.find("</script>", start) - start));
  CHECK(data["kind"] == "segments");
  CHECK(data["folder"] == "ksmc_report_@DATA@");
}
