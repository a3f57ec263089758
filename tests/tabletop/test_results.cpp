// Result outputs: scene_graph.json content and decisions, graph.dot, graph.png via
// Graphviz (or a warning when absent), overlay.png.
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "stdlib/tabletop/graph_dot.h"
#include "stdlib/tabletop/result_writer.h"
#include "stdlib/tabletop/scene_io.h"

using namespace ksmc::stdlib::tabletop;

namespace {

TabletopResult seed_result() {
  TabletopResult r;
  r.scene = load_scene(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json").scene;
  r.evidence = extract_evidence(r.scene);
  // Objects 0..6; 5 hovers (hidden), 6 intersects 1 (false), 1 undecided.
  r.probabilities = {{0.05, 0.10}, {0.45, 0.20}, {0.05, 0.10}, {0.05, 0.10}, {0.05, 0.10}, {0.20, 0.80}, {0.91, 0.46}};
  return r;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("decisions follow the seed's 0.4 / 0.6 reading", "[results]") {
  CHECK(decide(0.61) == std::optional<bool>(true));
  CHECK(decide(0.39) == std::optional<bool>(false));
  CHECK_FALSE(decide(0.5).has_value());
  CHECK_FALSE(decide(0.4).has_value());
  CHECK_FALSE(decide(0.6).has_value());
}

TEST_CASE("scene_graph.json content", "[results]") {
  const TabletopResult r = seed_result();
  const nlohmann::json j = scene_graph_json(r);
  REQUIRE(j["objects"].size() == 7);
  const auto& o6 = j["objects"][6];
  CHECK(o6["id"] == "6");
  CHECK(o6["stable"] == false);
  CHECK(o6["false_prob"] == 0.91);
  CHECK(o6["false"] == true);
  CHECK(o6["hidden"].is_null());
  CHECK(j["objects"][1]["false"].is_null());
  CHECK(j["objects"][5]["hidden"] == true);
  CHECK(j["objects"][5]["false"] == false);
  // Pose is written back in the camera frame: equal to the input file's pose.
  const auto input = nlohmann::json::parse(slurp(std::filesystem::path(KSMC_SOURCE_DIR) / "examples/tabletop/seed_example.json"));
  for (int k = 0; k < 3; ++k)
    CHECK(j["objects"][0]["pose"]["t"][k].get<double>() ==
          Approx(input["objects"][0]["pose"]["t"][k].get<double>()).margin(1e-8));
  const auto support = nlohmann::json::parse(R"([["0","table"],["1","table"],["2","table"],["3","table"],["4","3"]])");
  CHECK(j["support"] == support);
  // 6 touches the table, but it is decided false (0.91): a false estimate is no body, so the
  // scene graph has no edge of it. Undecided, it keeps its edge.
  CHECK(j["contact"] == nlohmann::json::array());
  CHECK(unstable_contact_edges(r.evidence) == std::vector<Edge>{{"6", "table"}});  // the evidence has it
  TabletopResult undecided = r;
  undecided.probabilities[6].false_prob = 0.5;
  CHECK(scene_graph_json(undecided)["contact"] == nlohmann::json::parse(R"([["6","table"]])"));
  // Boxes that cut each other are listed, false estimates included: 6 (decided false) cuts 1.
  CHECK(j["intersect"] == nlohmann::json::parse(R"([["1","6"]])"));
  CHECK(graph_dot(r).find("\"1\" -> \"6\" [dir=none, style=dotted") != std::string::npos);
  TabletopResult apart = r;
  apart.evidence.intersect[Evidence::body(6)][Evidence::body(1)] = apart.evidence.intersect[Evidence::body(1)][Evidence::body(6)] = 0;
  CHECK(scene_graph_json(apart)["intersect"] == nlohmann::json::array());
  // 3 decided false: it neither rests on the table nor carries 4.
  TabletopResult three = r;
  three.probabilities[3].false_prob = 0.7;
  CHECK(scene_graph_json(three)["support"] == nlohmann::json::parse(R"([["0","table"],["1","table"],["2","table"]])"));
  TabletopResult bad = r;
  bad.probabilities.pop_back();
  CHECK_THROWS_AS(scene_graph_json(bad), std::invalid_argument);
  bad = r;
  bad.probabilities[2].hidden_prob = 1.5;
  CHECK_THROWS_WITH(scene_graph_json(bad), Catch::Contains("object \"2\": probability 1.5"));
}

TEST_CASE("graph.dot draws support arrows and dashed contacts, none of a false estimate", "[results]") {
  const std::string dot = graph_dot(seed_result());
  CHECK(dot.find("\"3\" -> \"4\";") != std::string::npos);          // 3 supports 4
  CHECK(dot.find("\"table\" -> \"0\";") != std::string::npos);
  CHECK(dot.find("\"6\" -> \"table\"") == std::string::npos);  // 6 is decided false: no edge of it
  TabletopResult undecided = seed_result();
  undecided.probabilities[6].false_prob = 0.5;
  CHECK(graph_dot(undecided).find("\"6\" -> \"table\" [dir=none, style=dashed, constraint=false];") != std::string::npos);
  CHECK(dot.find("\"6\" [label=\"6\\nfalse 0.910  hidden 0.460\", fillcolor=\"#ff6666\"]") != std::string::npos);
  CHECK(dot.find("\"5\" [label=\"5\\nfalse 0.200  hidden 0.800\", fillcolor=\"#66ffff\"]") != std::string::npos);
  // Undecided (P(false) within 0.4-0.6, neither hidden): yellow. Decided on both: green.
  CHECK(graph_dot(undecided).find("\"6\" [label=\"6\\nfalse 0.500  hidden 0.460\", fillcolor=\"#ffee88\"]") != std::string::npos);
  CHECK(dot.find("\"0\" [label=\"0\\nfalse") != std::string::npos);
  CHECK(dot.find("fillcolor=\"#99dd99\"") != std::string::npos);
}

TEST_CASE("write_results writes every file; overlay colours; missing dot is a warning", "[results]") {
  const auto dir = std::filesystem::path(KSMC_BINARY_DIR) / "test_tabletop_results_out";
  std::filesystem::remove_all(dir);
  const TabletopResult r = seed_result();
  const ResultWriteReport rep = write_results(r, dir);
  CHECK(std::filesystem::exists(dir / "scene_graph.json"));
  CHECK(std::filesystem::exists(dir / "graph.dot"));
  CHECK(std::filesystem::exists(dir / "overlay.png"));
  CHECK(nlohmann::json::parse(slurp(dir / "scene_graph.json")) == scene_graph_json(r));
  if (std::filesystem::exists("/usr/bin/dot")) {
    CHECK(rep.warnings.empty());
    const std::string png = slurp(dir / "graph.png");
    REQUIRE(png.size() > 8);
    CHECK(png.substr(1, 3) == "PNG");
  }
  const cv::Mat img = cv::imread((dir / "overlay.png").string(), cv::IMREAD_COLOR);
  REQUIRE(!img.empty());
  CHECK(img.cols == 640);
  CHECK(img.rows == 480);
  int red = 0, cyan = 0, green = 0, yellow = 0;
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) {
      const auto& p = img.at<cv::Vec3b>(y, x);
      if (p[2] > 200 && p[1] < 60 && p[0] < 60) ++red;
      if (p[0] > 200 && p[1] > 200 && p[2] < 60) ++cyan;
      if (p[1] > 150 && p[0] < 60 && p[2] < 60) ++green;
      if (p[2] > 200 && p[1] > 200 && p[0] < 60) ++yellow;
    }
  CHECK(red > 100);    // object 6 (false)
  CHECK(cyan > 100);   // object 5 (hidden)
  CHECK(yellow > 100); // object 1 (undecided)
  CHECK(green > 500);  // the others

  ResultWriterOptions no_dot;
  no_dot.dot_executable = "/nonexistent/dot";
  const auto dir2 = dir / "nodot";
  const ResultWriteReport rep2 = write_results(r, dir2, no_dot);
  REQUIRE(rep2.warnings.size() == 1);
  CHECK(rep2.warnings[0].find("'dot' not found at /nonexistent/dot") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir2 / "graph.png"));
  CHECK(std::filesystem::exists(dir2 / "graph.dot"));

  // A background image that does not load: warning, blank canvas.
  TabletopResult with_bg = r;
  with_bg.scene.image = dir / "no_such_image.png";
  const ResultWriteReport rep3 = write_results(with_bg, dir / "bg", no_dot);
  CHECK(rep3.warnings.size() == 2);
  // Same input twice: byte-identical outputs.
  write_results(r, dir / "again");
  CHECK(slurp(dir / "again/scene_graph.json") == slurp(dir / "scene_graph.json"));
  CHECK(slurp(dir / "again/graph.dot") == slurp(dir / "graph.dot"));
  CHECK(slurp(dir / "again/overlay.png") == slurp(dir / "overlay.png"));
}
