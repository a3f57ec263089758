// The point-cloud readers (cloud_io: own PLY and PCD parsers): every format a sensor or
// PCL writes, read back exactly; every corrupt file (the cases fuzz_cloud targets: huge
// counts, truncated bodies, bad headers, missing fields) a CloudError naming the file
// and the place, never an abort or a huge allocation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "stdlib/tabletop/perception/cloud_io.h"

using namespace ksmc::stdlib::tabletop::perception;
namespace fs = std::filesystem;

namespace {

const std::vector<Eigen::Vector3d> kPoints = {{0, 0, 2.5}, {100, 0, 5.5}, {0, 100, 10.25}, {50, 50, 20}, {-25, 10, 1}};

fs::path write(const std::string& name, const std::string& bytes) {
  const fs::path d = fs::temp_directory_path() / "ksmc_cloud_io";
  fs::create_directories(d);
  std::ofstream(d / name, std::ios::binary) << bytes;
  return d / name;
}

template <typename T>
std::string raw(T v, bool big_endian = false) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &v, sizeof(T));
  if (big_endian) std::reverse(s.begin(), s.end());
  return s;
}

std::string ply_header(const std::string& format, const std::string& x_type = "float", const std::string& extra = "") {
  return "ply\nformat " + format + " 1.0\ncomment test\nelement vertex 5\nproperty " + x_type +
         " x\nproperty float y\nproperty float z\n" + extra + "end_header\n";
}

std::string pcd_header(const std::string& data, const std::string& fields = "x y z", const std::string& sizes = "4 4 4",
                       const std::string& types = "F F F", const std::string& points = "5") {
  std::string counts = "1";
  for (const char c : fields)
    if (c == ' ') counts += " 1";
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts +
         "\nWIDTH " + points +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + points + "\nDATA " + data + "\n";
}

void check_points(const fs::path& file, double scale = 1.0) {
  const Points got = load_cloud(file, scale == 1.0 ? Units::m : Units::mm);
  REQUIRE(got.size() == kPoints.size());
  for (std::size_t i = 0; i < got.size(); ++i) CHECK((got[i] - scale * kPoints[i]).norm() < 1e-9);
}

std::string error_of(const fs::path& file) {
  try {
    (void)load_cloud(file);
  } catch (const CloudError& e) {
    return e.what();
  }
  return "no error";
}

// The error names the file first, then contains `fragment`.
void check_error(const std::string& name, const std::string& bytes, const std::string& fragment) {
  const fs::path f = write(name, bytes);
  const std::string e = error_of(f);
  INFO(e);
  CHECK(e.rfind(f.string() + ": ", 0) == 0);
  CHECK(e.find(fragment) != std::string::npos);
}

}  // namespace

TEST_CASE("cloud_io reads PLY ascii, binary little and big endian, with colours and faces", "[perception][cloud_io]") {
  std::string ascii = ply_header("ascii", "float", "property uchar red\nelement face 1\nproperty list uchar int vertex_indices\n");
  for (const auto& p : kPoints) ascii += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + " 7\r\n";
  check_points(write("a.ply", ascii + "3 0 1 2\n"));
  check_points(write("a_mm.ply", ascii + "3 0 1 2\n"), 0.001);

  std::string le = ply_header("binary_little_endian", "double", "property uchar red\nelement face 1\nproperty list uchar int v\n");
  std::string be = ply_header("binary_big_endian");
  for (const auto& p : kPoints) {
    le += raw(p.x()) + raw(static_cast<float>(p.y())) + raw(static_cast<float>(p.z())) + raw(std::uint8_t{9});
    for (int k = 0; k < 3; ++k) be += raw(static_cast<float>(p[k]), true);
  }
  check_points(write("le.ply", le + raw(std::uint8_t{3}) + raw(0) + raw(1) + raw(2)));
  check_points(write("be.ply", be));
  check_points(write("ascii_save.ply", ply_text(kPoints)));
}

TEST_CASE("cloud_io reads PCD ascii, binary and binary_compressed", "[perception][cloud_io]") {
  std::string ascii = pcd_header("ascii", "x y z rgb", "4 4 4 4", "F F F U");
  std::string binary = pcd_header("binary", "x y z rgb", "4 8 4 4", "F F F U");
  std::string fields;  // binary_compressed: all x, then all y, then all z
  for (const auto& p : kPoints) {
    ascii += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + " 4278190080\n";
    binary += raw(static_cast<float>(p.x())) + raw(p.y()) + raw(static_cast<float>(p.z())) + raw(std::uint32_t{7});
  }
  for (int k = 0; k < 3; ++k)
    for (const auto& p : kPoints) fields += raw(static_cast<float>(p[k]));
  std::string lzf;  // literal runs of at most 32 bytes (control byte = length - 1)
  for (std::size_t i = 0; i < fields.size(); i += 32) {
    const std::string chunk = fields.substr(i, 32);
    lzf += static_cast<char>(chunk.size() - 1) + chunk;
  }
  check_points(write("a.pcd", ascii));
  check_points(write("b.pcd", binary));
  check_points(write("c.pcd", pcd_header("binary_compressed") + raw(static_cast<std::uint32_t>(lzf.size())) +
                                  raw(static_cast<std::uint32_t>(fields.size())) + lzf));
  // A back reference: 60 bytes of zeros as one literal zero and a copy of 59.
  const std::string zeros = pcd_header("binary_compressed", "x y z", "4 4 4", "F F F", "5");
  const std::string refs = std::string(1, '\0') + std::string(1, '\0') + std::string(1, '\xe0') + std::string(1, '\x32') +
                           std::string(1, '\0');
  // They decompress to five points at (0, 0, 0): missing returns only, so the error counts them.
  check_error("z.pcd", zeros + raw(std::uint32_t{5}) + raw(std::uint32_t{60}) + refs, "all 5 points are missing returns");
}

TEST_CASE("cloud_io refuses corrupt PLY files, naming the file and the place", "[perception][cloud_io]") {
  check_error("notply.ply", "PLY\n", "header line 1: not a PLY file");
  check_error("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n", "no \"end_header\" line");
  check_error("fmt.ply", "ply\nformat binary 2.0\nend_header\n", "header line 2: expected \"format ascii|");
  check_error("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\nend_header\n",
              "header line 3: expected \"element <name> <count>\" with a count of at most the file size");
  check_error("big.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\nproperty float y\n"
                         "property float z\nend_header\n" + std::string(24, '\0'),
              "header line 3: 100 vertex elements of at least 12 bytes need 1200 bytes, the file has 24 left");
  check_error("trunc_list.ply", ply_header("binary_little_endian", "float", "element face 1\nproperty list uchar int v\n") +
                                    std::string(60, '\0') + raw(std::uint8_t{200}) + raw(1),
              "list length 200 does not fit in the file");
  check_error("short.ply", ply_header("ascii") + "1 2 3\n4 5 6\n" + std::string(30, ' '),
              "the body ends in vertex 2 of 5 (header line 4)");
  check_error("few.ply", ply_header("ascii") + "1 2 3\n4 5 6\n", "header line 4: 5 vertex elements cannot fit in the 12 bytes");
  check_error("word.ply", ply_header("ascii") + "1 2 3\n4 five 6\n" + std::string(30, ' '), "line 10: vertex 1: \"five\" is not a number");
  check_error("noz.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
              "header line 3: element vertex has no scalar property \"z\"");
  check_error("novertex.ply", "ply\nformat ascii 1.0\nelement face 1\nproperty float a\nend_header\n1\n",
              "no \"element vertex\" in the header");
  check_error("noprops.ply", "ply\nformat ascii 1.0\nelement vertex 9\nend_header\n",
              "header line 3: element \"vertex\" has no properties");
  check_error("keyword.ply", "ply\nformat ascii 1.0\nelements vertex 1\nend_header\n", "header line 3: unknown header keyword");
  check_error("typo.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty flaot x\nend_header\n",
              "header line 4: expected \"property <type> <name>\"");
}

TEST_CASE("cloud_io reads regular files only", "[perception][cloud_io]") {
  CHECK(error_of("/dev/zero") == "/dev/zero: expected a regular file");
  CHECK(error_of("/nonexistent/x.ply") == "/nonexistent/x.ply: cannot open file");
  const fs::path dir = fs::temp_directory_path() / "ksmc_cloud_io" / "folder.ply";
  fs::create_directories(dir);
  CHECK(error_of(dir) == dir.string() + ": expected a regular file");
}

TEST_CASE("cloud_io refuses corrupt PCD files, naming the file and the place", "[perception][cloud_io]") {
  check_error("nodata.pcd", "VERSION 0.7\nFIELDS x y z\n", "no \"DATA\" line in the header");
  check_error("nox.pcd", pcd_header("ascii", "a y z") + "1 2 3\n", "header line 3: no field \"x\"");
  check_error("size.pcd", pcd_header("ascii", "x y z", "4 4") + "1 2 3\n", "3 fields, but SIZE, TYPE and COUNT give 2,");
  check_error("type.pcd", pcd_header("ascii", "x y z", "4 4 2", "F F F") + "1 2 3\n", "field \"z\": SIZE 2 TYPE F");
  check_error("huge.pcd", pcd_header("binary", "x y z", "4 4 4", "F F F", "99999999999") + "abc",
              "header line 7: WIDTH expects one count of at most ");
  check_error("area.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 5000\nHEIGHT 5000\nDATA binary\n" + std::string(12, '\0'),
              "25000000 points of 12 bytes need 300000000 bytes, the file has 12 after the header (truncated?)");
  check_error("trunc.pcd", pcd_header("binary", "x y z", "4 4 4", "F F F", "100") + std::string(100, '\0'),
              "100 points of 12 bytes need 1200 bytes, the file has 100 after the header (truncated?)");
  check_error("short.pcd", pcd_header("ascii") + "1 2 3\n" + std::string(30, ' '), "the body ends in point 1 of 5");
  check_error("few.pcd", pcd_header("ascii") + "1 2 3\n", "5 points of 3 values cannot fit in the 6 bytes after the header");
  check_error("packed.pcd", pcd_header("binary_compressed") + raw(std::uint32_t{1000}) + raw(std::uint32_t{60}) + "x",
              "compressed size 1000 exceeds the 1 bytes that follow");
  check_error("unpacked.pcd", pcd_header("binary_compressed") + raw(std::uint32_t{1}) + raw(std::uint32_t{61}) + "x",
              "uncompressed size 61 is not 5 points x 12 bytes");
  check_error("lzf.pcd", pcd_header("binary_compressed") + raw(std::uint32_t{3}) + raw(std::uint32_t{60}) + std::string("\xe0\x32\x00", 3),
              "corrupt compressed data");
  check_error("dims.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 2\nPOINTS 5\nDATA ascii\n",
              "WIDTH 3 x HEIGHT 2 is not POINTS 5");
  check_error("keyword.pcd", "ply\nformat ascii 1.0\n", "header line 1: unknown header keyword \"ply\" (not a PCD file?)");
}

TEST_CASE("cloud_io leaves out points at (0, 0, 0), a depth sensor's missing returns", "[perception][cloud_io]") {
  std::vector<Eigen::Vector3d> with_missing = kPoints;
  with_missing.insert(with_missing.begin() + 2, 3, Eigen::Vector3d::Zero());
  with_missing.emplace_back(0, 0, 0);
  std::size_t missing = 99;
  const Points read = load_cloud(write("missing.ply", ply_text(with_missing)), Units::m, &missing);
  CHECK(missing == 4);
  REQUIRE(read.size() == kPoints.size());
  for (std::size_t i = 0; i < read.size(); ++i) CHECK((read[i] - kPoints[i]).norm() < 1e-6);
  // Nothing but missing returns: an empty cloud, named.
  check_error("all_missing.ply", ply_text({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}), "all 2 points are missing returns");
}

TEST_CASE("cloud_io leaves out NaN points of an organised PCD, PCL's missing returns", "[perception][cloud_io]") {
  // A 3 x 2 image-shaped cloud: kPoints' first four, and two pixels with no return.
  const std::string organised = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 2\n"
                                "POINTS 6\nDATA ascii\n0 0 2.5\nnan nan nan\n100 0 5.5\n0 100 10.25\nnan nan nan\n50 50 20\n";
  std::size_t missing = 0;
  const Points read = load_cloud(write("organised.pcd", organised), Units::m, &missing);
  CHECK(missing == 2);
  REQUIRE(read.size() == 4);
  for (std::size_t i = 0; i < read.size(); ++i) CHECK((read[i] - kPoints[i]).norm() < 1e-6);
  // One NaN coordinate is a corrupt point even there; so is an all-NaN point of an unorganised cloud.
  std::string partial = organised;
  partial.replace(partial.find("50 50 20"), 8, "50 nan 20");
  check_error("partial.pcd", partial, "point 5: not a finite coordinate (50, nan, 20)");
  check_error("flat.pcd", pcd_header("ascii", "x y z", "4 4 4", "F F F", "2") + "0 0 1\nnan nan nan\n",
              "point 1: not a finite coordinate (nan, nan, nan) (NaN marks a missing return only in an organised PCD");
}
