// Bad input to `tabletop --stereo` and `ksmc-objdb`: each a non-zero exit and a message
// naming the file (images of different sizes, missing / malformed calibration, an object
// with no features, no table anywhere, an unreadable image, arguments that do not fit).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "stdlib/tabletop/perception/stereo/object_db.h"
#include "stereo_scenes.h"

namespace fs = std::filesystem;
namespace ts = ksmc::tests::stereo;

namespace {

struct Outcome {
  int code = 0;
  std::string text;
};

Outcome run(const std::string& exe, const std::string& args, const fs::path& log) {
  const std::string cmd = exe + " " + args + " > " + log.string() + " 2>&1";
  Outcome o;
  o.code = std::system(cmd.c_str());
  std::ifstream in(log);
  o.text.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return o;
}

struct Fixture {
  fs::path dir = ts::fresh_dir("cli");
  fs::path left = dir / "left.png", right = dir / "right.png", calib = dir / "stereo.yaml", db = dir / "db";
  Fixture() {
    const ts::sy::Rig rig = ts::standard_rig();
    const cv::Mat grey(rig.height, rig.width, CV_8U, cv::Scalar(100));
    cv::imwrite(left.string(), grey);
    cv::imwrite(right.string(), grey);
    ts::st::save_calib(calib, ts::sy::rig_calib(rig));
    ts::sy::write_object_folder(db, ts::sy::textured_box("box", {0.1, 0.08, 0.06}, ts::sy::upright(0, 0, 0.03, 0), 1));
  }
  std::string args(const fs::path& l, const fs::path& r, const fs::path& c, const fs::path& d) const {
    return "--stereo " + l.string() + " " + r.string() + " --calib " + c.string() + " --db " + d.string() + " --out " +
           (dir / "out").string() + " --iterations 10";
  }
  Outcome tabletop(const std::string& a) const { return run(KSMC_TABLETOP_EXE, a, dir / "log.txt"); }
};

}  // namespace

TEST_CASE("tabletop --stereo: a featureless pair gives a scene without objects", "[stereo][cli]") {
  const Fixture f;
  const Outcome o = f.tabletop(f.args(f.left, f.right, f.calib, f.db));
  INFO(o.text);
  CHECK(o.code == 0);
  CHECK(fs::exists(f.dir / "out" / "scene.json"));
}

TEST_CASE("tabletop --stereo: image paths with spaces", "[stereo][cli]") {
  // Each of the two words of --stereo is one path, spaces and all (the shell quotes them).
  const Fixture f;
  const fs::path spaced = f.dir / "left and right";
  fs::create_directories(spaced);
  fs::copy_file(f.left, spaced / "left image.png");
  fs::copy_file(f.right, spaced / "right image.png");
  const std::string quoted = "\"" + (spaced / "left image.png").string() + "\" \"" + (spaced / "right image.png").string() + "\"";
  const Outcome o = f.tabletop("--stereo " + quoted + " --calib " + f.calib.string() + " --db " + f.db.string() + " --out " +
                               (f.dir / "out").string() + " --iterations 10");
  INFO(o.text);
  CHECK(o.code == 0);
  CHECK(fs::exists(f.dir / "out" / "scene.json"));
}

TEST_CASE("tabletop --stereo: bad input names the file and exits non-zero", "[stereo][cli]") {
  const Fixture f;
  SECTION("images of different sizes") {
    const fs::path small = f.dir / "small.png";
    cv::imwrite(small.string(), cv::Mat(240, 320, CV_8U, cv::Scalar(90)));
    const Outcome o = f.tabletop(f.args(f.left, small, f.calib, f.db));
    INFO(o.text);
    CHECK(o.code != 0);
    CHECK(o.text.find(small.string() + ": image is 320x240") != std::string::npos);
    CHECK(o.text.find("differ in size") != std::string::npos);
  }
  SECTION("missing calibration") {
    const Outcome o = f.tabletop(f.args(f.left, f.right, f.dir / "none.yaml", f.db));
    INFO(o.text);
    CHECK(o.code != 0);
    CHECK(o.text.find((f.dir / "none.yaml").string() + ": calibration file not found") != std::string::npos);
  }
  SECTION("malformed calibration: not YAML, an entry missing, not a rotation") {
    const fs::path bad = f.dir / "bad.yaml";
    std::ofstream(bad) << "%YAML:1.0\nimage_width: [\n";
    Outcome o = f.tabletop(f.args(f.left, f.right, bad, f.db));
    INFO(o.text);
    CHECK(o.code != 0);
    CHECK(o.text.find(bad.string() + ": ") != std::string::npos);
    std::ofstream(bad) << "%YAML:1.0\nimage_width: 640\nimage_height: 480\n";
    o = f.tabletop(f.args(f.left, f.right, bad, f.db));
    CHECK(o.code != 0);
    CHECK(o.text.find(bad.string() + ": K_left: missing") != std::string::npos);
    std::ofstream(bad) << "%YAML:1.0\nimage_width: 640\nimage_height: 480\nK_left: [615, 0, 320, 0, 615, 240, 0, 0, 1]\n"
                          "K_right: [615, 0, 320, 0, 615, 240, 0, 0, 1]\nR: [1, 0, 0, 0, 2, 0, 0, 0, 1]\nt: [-0.08, 0, 0]\n";
    o = f.tabletop(f.args(f.left, f.right, bad, f.db));
    CHECK(o.code != 0);
    CHECK(o.text.find(bad.string() + ": R: not a rotation matrix") != std::string::npos);
  }
  SECTION("a database object with no features") {
    const fs::path blank = f.db / "blank";
    fs::create_directories(blank);
    std::ofstream(blank / "object.json") << "{\"size\": [0.1, 0.1, 0.1]}";
    for (const char* face : ksmc::stdlib::tabletop::perception::stereo::kFaceNames)
      cv::imwrite((blank / (std::string("face_") + face + ".png")).string(), cv::Mat(200, 200, CV_8U, cv::Scalar(128)));
    const Outcome o = f.tabletop(f.args(f.left, f.right, f.calib, f.db));
    INFO(o.text);
    CHECK(o.code != 0);
    CHECK(o.text.find(blank.string() + ": no SIFT features") != std::string::npos);
    const Outcome t = run(KSMC_OBJDB_EXE, f.db.string(), f.dir / "objdb.txt");
    INFO(t.text);
    CHECK(t.code != 0);
    CHECK(t.text.find(blank.string() + ": no SIFT features") != std::string::npos);
  }
  SECTION("no table: neither in the calibration nor among the stereo points") {
    auto calib = ts::sy::rig_calib(ts::standard_rig());
    calib.table_in_left.reset();
    const fs::path no_table = f.dir / "no_table.yaml";
    ts::st::save_calib(no_table, calib);
    const Outcome o = f.tabletop(f.args(f.left, f.right, no_table, f.db));
    INFO(o.text);
    CHECK(o.code != 0);
    CHECK(o.text.find(f.left.string() + ": no table") != std::string::npos);
  }
  SECTION("unreadable image") {
    const fs::path junk = f.dir / "junk.png";
    std::ofstream(junk) << "not a png";
    const Outcome o = f.tabletop(f.args(junk, f.right, f.calib, f.db));
    INFO(o.text);
    CHECK(o.code != 0);
    CHECK(o.text.find(junk.string() + ": not a readable image") != std::string::npos);
  }
  SECTION("arguments: a positional scene.json next to --stereo, --stereo without --db") {
    Outcome o = f.tabletop("x.json " + f.args(f.left, f.right, f.calib, f.db));
    CHECK(o.code != 0);
    o = f.tabletop("--stereo " + f.left.string() + " " + f.right.string() + " --calib " + f.calib.string() + " --out " +
                   (f.dir / "o2").string());
    CHECK(o.code != 0);
    CHECK(o.text.find("--db") != std::string::npos);
  }
}

TEST_CASE("ksmc-objdb writes model.yml that load_database reads back", "[stereo][cli]") {
  const Fixture f;
  const Outcome o = run(KSMC_OBJDB_EXE, f.db.string(), f.dir / "objdb.txt");
  INFO(o.text);
  REQUIRE(o.code == 0);
  REQUIRE(fs::exists(f.db / "box" / "model.yml"));
  const auto built = ts::st::build_model(f.db / "box");
  const auto loaded = ts::st::load_database(f.db);
  REQUIRE(loaded.size() == 1);
  CHECK(loaded[0].points.size() == built.points.size());
  CHECK(loaded[0].points.size() > 100);
  CHECK((loaded[0].points.back() - built.points.back()).norm() < 1e-12);
  CHECK(cv::norm(loaded[0].descriptors, built.descriptors) < 1e-6);
}
