// Every bad-input case of the loader: a typed MapLoadError whose message names the file (and the
// YAML line where there is one). Bad files are made in a temp folder.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "stdlib/indoor/io/map_error.h"
#include "stdlib/indoor/io/map_loader.h"
#include "tests/indoor_io/temp_dir.h"

using namespace ksmc::stdlib::indoor::io;
using ksmc::tests::TempDir;

namespace {

std::string small_pgm() {
  std::string s = "P5\n4 4\n255\n";
  for (int i = 0; i < 16; ++i) s += static_cast<char>(i % 2 == 0 ? 254 : 0);
  return s;
}

// Runs `fn`, requires a MapLoadError of `kind`, returns it for further checks.
template <typename Fn>
MapLoadError expect_error(MapErrorKind kind, Fn&& fn) {
  try {
    fn();
  } catch (const MapLoadError& e) {
    INFO(e.what());
    CHECK(std::string(to_string(e.kind())) == to_string(kind));
    return e;
  }
  FAIL("no MapLoadError thrown");
  throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("missing or unreadable files") {
  TempDir dir("bad_missing");
  SECTION("bare image missing") {
    const auto p = dir / "nope.png";
    const auto e = expect_error(MapErrorKind::Unreadable, [&] { load_map_image(p); });
    CHECK_THAT(e.what(), Catch::Contains(p.string()) && Catch::Contains("does not exist"));
    CHECK(e.file() == p);
  }
  SECTION("YAML missing") {
    const auto p = dir / "nope.yaml";
    const auto e = expect_error(MapErrorKind::Unreadable, [&] { load_map(p); });
    CHECK_THAT(e.what(), Catch::Contains("nope.yaml"));
  }
  SECTION("image referenced by the YAML missing") {
    const auto y = dir.write("m.yaml", "resolution: 0.05\nimage: gone.pgm\n");
    const auto e = expect_error(MapErrorKind::Unreadable, [&] { load_map_yaml(y); });
    CHECK_THAT(e.what(), Catch::Contains("gone.pgm") && Catch::Contains("m.yaml:2"));
  }
  SECTION("a directory instead of an image") {
    const auto e = expect_error(MapErrorKind::Unreadable, [&] { load_map_image(dir.path()); });
    CHECK_THAT(e.what(), Catch::Contains("directory"));
  }
}

TEST_CASE("bad YAML: missing keys, non-numeric values, syntax, ranges") {
  TempDir dir("bad_yaml");
  dir.write("m.pgm", small_pgm());
  SECTION("no resolution") {
    const auto y = dir.write("a.yaml", "image: m.pgm\norigin: [0, 0, 0]\n");
    const auto e = expect_error(MapErrorKind::YamlMissingKey, [&] { load_map_yaml(y); });
    CHECK_THAT(e.what(), Catch::Contains("a.yaml") && Catch::Contains("resolution"));
  }
  SECTION("no image") {
    const auto y = dir.write("b.yaml", "resolution: 0.05\n");
    const auto e = expect_error(MapErrorKind::YamlMissingKey, [&] { load_map_yaml(y); });
    CHECK_THAT(e.what(), Catch::Contains("'image'"));
  }
  SECTION("non-numeric resolution names the line") {
    const auto y = dir.write("c.yaml", "image: m.pgm\nresolution: five cm\n");
    const auto e = expect_error(MapErrorKind::YamlBadValue, [&] { load_map_yaml(y); });
    CHECK(e.line() == 2);
    CHECK_THAT(e.what(), Catch::Contains("c.yaml:2") && Catch::Contains("five cm"));
  }
  SECTION("non-numeric origin element names the line") {
    const auto y = dir.write("d.yaml", "image: m.pgm\nresolution: 0.05\n\norigin: [0, north, 0]\n");
    const auto e = expect_error(MapErrorKind::YamlBadValue, [&] { load_map_yaml(y); });
    CHECK(e.line() == 4);
  }
  SECTION("non-numeric threshold") {
    const auto y = dir.write("e.yaml", "image: m.pgm\nresolution: 0.05\nfree_thresh: [1]\n");
    const auto e = expect_error(MapErrorKind::YamlBadValue, [&] { load_map_yaml(y); });
    CHECK(e.line() == 3);
  }
  SECTION("negative resolution, thresholds out of order, bad mode, bad negate") {
    expect_error(MapErrorKind::YamlBadValue, [&] {
      load_map_yaml(dir.write("f.yaml", "image: m.pgm\nresolution: -0.05\n"));
    });
    expect_error(MapErrorKind::YamlBadValue, [&] {
      load_map_yaml(dir.write("g.yaml", "image: m.pgm\nresolution: 0.05\nfree_thresh: 0.9\n"));
    });
    const auto e = expect_error(MapErrorKind::YamlBadValue, [&] {
      load_map_yaml(dir.write("h.yaml", "image: m.pgm\nresolution: 0.05\nmode: fancy\n"));
    });
    CHECK(e.line() == 3);
    expect_error(MapErrorKind::YamlBadValue, [&] {
      load_map_yaml(dir.write("i.yaml", "image: m.pgm\nresolution: 0.05\nnegate: maybe\n"));
    });
    expect_error(MapErrorKind::YamlBadValue, [&] {
      load_map_yaml(dir.write("j.yaml", "image: m.pgm\nresolution: .nan\n"));
    });
  }
  SECTION("syntax error names the line") {
    const auto y = dir.write("k.yaml", "image: m.pgm\nresolution: 0.05\norigin: [0, 0\n");
    const auto e = expect_error(MapErrorKind::YamlSyntax, [&] { load_map_yaml(y); });
    CHECK(e.line() >= 3);
    CHECK_THAT(e.what(), Catch::Contains("k.yaml:"));
  }
  SECTION("not a mapping") {
    expect_error(MapErrorKind::YamlBadValue,
                 [&] { load_map_yaml(dir.write("l.yaml", "- just\n- a list\n")); });
  }
  SECTION("bad caller resolution") {
    YamlLoadOptions o;
    o.resolution_override = 0.0;
    expect_error(MapErrorKind::BadOption, [&] {
      load_map_yaml(dir.write("m.yaml", "image: m.pgm\nresolution: 0.05\n"), o);
    });
  }
}

TEST_CASE("bad images: non-image bytes, truncation, unsupported types") {
  TempDir dir("bad_image");
  SECTION("text file") {
    const auto p = dir.write("notes.png", "hello, this is not a map\n");
    const auto e = expect_error(MapErrorKind::NotAnImage, [&] { load_map_image(p); });
    CHECK_THAT(e.what(), Catch::Contains("notes.png") && Catch::Contains("68 65 6c 6c"));
  }
  SECTION("empty file") {
    const auto e = expect_error(MapErrorKind::NotAnImage,
                                [&] { load_map_image(dir.write("empty.pgm", "")); });
    CHECK_THAT(e.what(), Catch::Contains("empty"));
  }
  SECTION("colour PPM is refused by name") {
    const auto e = expect_error(MapErrorKind::NotAnImage,
                                [&] { load_map_image(dir.write("c.ppm", "P6\n4 4\n255\n")); });
    CHECK_THAT(e.what(), Catch::Contains("P6"));
  }
  SECTION("truncated P5 data") {
    std::string s = small_pgm();
    s.resize(s.size() - 5);
    const auto p = dir.write("t.pgm", s);
    const auto e = expect_error(MapErrorKind::Truncated, [&] { load_map_image(p); });
    CHECK_THAT(e.what(), Catch::Contains("t.pgm") && Catch::Contains("16 bytes") &&
                             Catch::Contains("file has 11"));
  }
  SECTION("truncated P5 header") {
    expect_error(MapErrorKind::Truncated, [&] { load_map_image(dir.write("h.pgm", "P5\n4 4\n")); });
  }
  SECTION("truncated P2 data") {
    const auto e = expect_error(MapErrorKind::Truncated, [&] {
      load_map_image(dir.write("t2.pgm", "P2\n3 3\n255\n0 0 0\n254 254\n"));
    });
    CHECK_THAT(e.what(), Catch::Contains("file has 5"));
  }
  SECTION("garbage in PGM header") {
    expect_error(MapErrorKind::BadHeader,
                 [&] { load_map_image(dir.write("g.pgm", "P5\nwide 4\n255\n")); });
    expect_error(MapErrorKind::BadHeader,
                 [&] { load_map_image(dir.write("m.pgm", "P5\n4 4\n70000\n")); });
  }
  SECTION("sample above maxval") {
    expect_error(MapErrorKind::BadHeader,
                 [&] { load_map_image(dir.write("v.pgm", "P2\n3 3\n100\n0 0 0 0 0 0 0 0 200\n")); });
  }
  SECTION("truncated PNG") {
    cv::Mat1b img(40, 40, static_cast<std::uint8_t>(254));
    img(20, 20) = 0;
    std::vector<unsigned char> buf;
    REQUIRE(cv::imencode(".png", img, buf));
    const std::string cut(buf.begin(), buf.begin() + static_cast<long>(buf.size() / 2));
    const auto e = expect_error(MapErrorKind::Truncated,
                                [&] { load_map_image(dir.write("cut.png", cut)); });
    CHECK_THAT(e.what(), Catch::Contains("cut.png"));
    expect_error(MapErrorKind::Truncated,
                 [&] { load_map_image(dir.write("stub.png", std::string(cut.substr(0, 12)))); });
  }
}

TEST_CASE("maps that are too small, too large, or have no free cell") {
  TempDir dir("bad_size");
  SECTION("1x1") {
    const auto e = expect_error(MapErrorKind::TooSmall,
                                [&] { load_map_image(dir.write("one.pgm", "P5 1 1 255\n\xfe")); });
    CHECK_THAT(e.what(), Catch::Contains("1x1") && Catch::Contains("3x3"));
  }
  SECTION("huge PGM header is refused before reading pixels") {
    const auto p = dir.write("huge.pgm", "P5\n20000 20000\n255\n");  // 4e8 cells, no data at all
    const auto e = expect_error(MapErrorKind::TooLarge, [&] { load_map_image(p); });
    CHECK_THAT(e.what(), Catch::Contains("20000x20000") && Catch::Contains("2.5e8") &&
                             Catch::Contains("huge.pgm"));
  }
  SECTION("huge PNG header is refused before decoding") {
    std::string s("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
    const auto be = [&](std::uint32_t v) {
      for (int k = 3; k >= 0; --k) s += static_cast<char>((v >> (8 * k)) & 0xff);
    };
    be(100000);
    be(100000);
    s += std::string("\x08\x00\x00\x00\x00", 5);
    const auto e = expect_error(MapErrorKind::TooLarge,
                                [&] { load_map_image(dir.write("huge.png", s)); });
    CHECK_THAT(e.what(), Catch::Contains("100000x100000"));
  }
  SECTION("no free cells, through the YAML too") {
    std::string s = "P5 5 5 255\n";
    s += std::string(25, '\0');
    const auto p = dir.write("dark.pgm", s);
    const auto e = expect_error(MapErrorKind::NoFreeCells, [&] { load_map_image(p); });
    CHECK_THAT(e.what(), Catch::Contains("dark.pgm") && Catch::Contains("25 occupied"));
    const auto y = dir.write("dark.yaml", "image: dark.pgm\nresolution: 0.05\n");
    const auto e2 = expect_error(MapErrorKind::NoFreeCells, [&] { load_map_yaml(y); });
    CHECK_THAT(e2.what(), Catch::Contains("dark.yaml"));
    // The same map is fine when negated.
    CHECK_NOTHROW(load_map_yaml(dir.write("neg.yaml", "image: dark.pgm\nresolution: 0.05\nnegate: 1\n")));
  }
}
