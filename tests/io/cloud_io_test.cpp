// Point cloud files: round trips through every encoding, hand-built files for the layouts the
// writer never produces (extra fields, binary_compressed, PLY faces), PCL's real test clouds,
// and located errors for bad input.
#include "rigdesign/io/cloud/cloud_io.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>

#include "rigdesign/model/input_error.hpp"
#include "support/byte_text.hpp"
#include "support/temp_folder.hpp"

using namespace rigdesign;
using namespace rigdesign::test;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Values chosen to catch lossy text: no short decimal form, extremes of float's range.
model::PointCloud small_cloud() {
  model::PointCloud cloud;
  cloud.points = {{0.1f, -0.2f, 0.3f},
                  {1.0f / 3.0f, 2.0f / 3.0f, -1.0e-7f},
                  {123456.789f, -9.87654e-3f, 42.0f},
                  // the largest magnitude read_cloud accepts, the smallest normal float
                  {-1.0e8f, -1.17549435e-38f, 0.0f}};
  cloud.origin = {1.5f, -2.25f, 0.125f};
  cloud.orientation = Eigen::Quaternionf(0.9f, 0.1f, -0.3f, 0.2f).normalized();
  return cloud;
}

// An LZF stream with literal runs only: a control byte (run length - 1) before each run of
// at most 32 bytes. Valid LZF, just not compressed.
std::string literal_only_lzf(const std::string& bytes) {
  constexpr std::size_t kLongestLiteralRun = 32;
  std::string stream;
  for (std::size_t at = 0; at < bytes.size(); at += kLongestLiteralRun) {
    const std::string run = bytes.substr(at, kLongestLiteralRun);
    stream += static_cast<char>(run.size() - 1);
    stream += run;
  }
  return stream;
}

std::string compressed_body(const std::string& stream, std::size_t decompressed_size) {
  return bytes_of(static_cast<std::uint32_t>(stream.size())) +
         bytes_of(static_cast<std::uint32_t>(decompressed_size)) + stream;
}

std::string pcd_header(const std::string& fields, const std::string& sizes,
                       const std::string& types, const std::string& counts, std::size_t points,
                       const std::string& data) {
  const std::string n = std::to_string(points);
  return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " +
         sizes + "\nTYPE " + types + "\nCOUNT " + counts + "\nWIDTH " + n +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + n + "\nDATA " + data + "\n";
}

std::string xyz_pcd_header(std::size_t points, const std::string& data) {
  return pcd_header("x y z", "4 4 4", "F F F", "1 1 1", points, data);
}

}  // namespace

TEST_CASE("clouds survive a round trip through every format and encoding") {
  TempFolder folder;
  const model::PointCloud original = small_cloud();
  struct Case {
    const char* file;
    io::CloudEncoding encoding;
    const char* format;
  };
  const std::vector<Case> cases = {
      {"c.pcd", io::CloudEncoding::ascii, "pcd ascii"},
      {"c.pcd", io::CloudEncoding::binary, "pcd binary"},
      {"c.PLY", io::CloudEncoding::ascii, "ply ascii"},
      {"c.ply", io::CloudEncoding::binary, "ply binary_little_endian"}};
  for (const Case& c : cases) {
    INFO(c.format);
    const std::string path = folder.path() + "/" + c.file;
    io::write_cloud(path, original, c.encoding);
    io::CloudReadReport report;
    const model::PointCloud read = io::read_cloud(path, &report);
    CHECK(report.format == c.format);
    CHECK(report.points_in_file == original.size());
    CHECK(report.dropped_non_finite == 0);
    CHECK(report.ignored_fields.empty());
    REQUIRE(read.size() == original.size());
    for (std::size_t i = 0; i < read.size(); ++i) {
      // Binary copies the floats; ascii writes the shortest text that reads back to the
      // same float, so both are exact (stricter than the 1e-6 relative that text needs).
      CHECK(read.points[i] == original.points[i]);
    }
    // PCD keeps the pose in VIEWPOINT, PLY in write_cloud's viewpoint comment.
    CHECK(read.origin == original.origin);
    CHECK(read.orientation.coeffs().isApprox(original.orientation.coeffs(), 1e-6f));
  }
}

TEST_CASE("a point beyond 1e8 m is refused with the file and its index, never filtered") {
  // Issue 16: one point at x = 3e19 crashed the outlier filter's neighbour grid.
  TempFolder folder;
  model::PointCloud cloud = small_cloud();
  cloud.points[2].x() = 3e19f;
  for (const char* name : {"far.pcd", "far.ply"}) {
    for (const io::CloudEncoding encoding : {io::CloudEncoding::ascii, io::CloudEncoding::binary}) {
      const std::string path = folder.path() + "/" + name;
      io::write_cloud(path, cloud, encoding);
      try {
        io::read_cloud(path);
        FAIL("read_cloud accepted a point at 3e19 m");
      } catch (const model::InputError& error) {
        const std::string message = error.diagnostics().front().message();
        CHECK(message.find(path + ": point 2: lies at (3e+19,") == 0);
        CHECK(message.find("beyond +-1e+08 m") != std::string::npos);
      }
    }
  }
  // Just inside the limit is a cloud like any other.
  cloud.points[2].x() = -1e8f;
  io::write_cloud(folder.path() + "/near.pcd", cloud, io::CloudEncoding::binary);
  CHECK(io::read_cloud(folder.path() + "/near.pcd").size() == cloud.size());
}

TEST_CASE("non-finite points are dropped and counted, empty clouds are valid") {
  TempFolder folder;
  model::PointCloud cloud;
  cloud.points = {
      {1, 2, 3}, {kNaN, kNaN, kNaN}, {4, std::numeric_limits<float>::infinity(), 6}, {7, 8, 9}};
  for (const io::CloudEncoding encoding : {io::CloudEncoding::ascii, io::CloudEncoding::binary}) {
    for (const char* name : {"/n.pcd", "/n.ply"}) {
      const std::string path = folder.path() + name;
      io::write_cloud(path, cloud, encoding);
      io::CloudReadReport report;
      const model::PointCloud read = io::read_cloud(path, &report);
      CHECK(report.points_in_file == 4);
      CHECK(report.dropped_non_finite == 2);
      REQUIRE(read.size() == 2);
      CHECK(read.points[1] == model::Point3f(7, 8, 9));

      io::write_cloud(path, model::PointCloud{}, encoding);
      CHECK(io::read_cloud(path).empty());
    }
  }
}

TEST_CASE("write_cloud refuses an unknown extension and leaves no file") {
  TempFolder folder;
  const std::string path = folder.path() + "/cloud.xyz";
  try {
    io::write_cloud(path, small_cloud(), io::CloudEncoding::ascii);
    FAIL("no InputError");
  } catch (const model::InputError& e) {
    CHECK(std::string(e.what()).find("cloud.xyz: output:") != std::string::npos);
  }
  CHECK(folder.entries() == 0);
}

TEST_CASE("PCD fields besides x y z are read past in every encoding") {
  // rgb (U 4) before x, a three-value descriptor (COUNT 3) between x and y, z as a double.
  TempFolder folder;
  const std::string fields = "rgb x desc y z";
  const std::string sizes = "4 4 2 4 8";
  const std::string types = "U F I F F";
  const std::string counts = "1 1 3 1 1";
  const std::vector<model::Point3f> expected = {{1.5f, -2.5f, 3.25f}, {-0.1f, 0.2f, 1e-3f}};
  std::string records;
  std::string soa;  // binary_compressed: all rgb, then all x, ..., field after field
  std::string text;
  for (const model::Point3f& p : expected) {
    records += bytes_of(std::uint32_t{0xff8040}) + bytes_of(p.x()) + bytes_of(std::int16_t{-1}) +
               bytes_of(std::int16_t{2}) + bytes_of(std::int16_t{3}) + bytes_of(p.y()) +
               bytes_of(static_cast<double>(p.z()));
    text += "16744512 " + std::to_string(p.x()) + " -1 2 +3 " + std::to_string(p.y()) + " " +
            std::to_string(p.z()) + "\n";
  }
  const std::size_t n = expected.size();
  for (std::size_t i = 0; i < n; ++i) soa += bytes_of(std::uint32_t{0xff8040});
  for (std::size_t i = 0; i < n; ++i) soa += bytes_of(expected[i].x());
  for (std::size_t i = 0; i < n; ++i) soa += std::string(6, '\x01');
  for (std::size_t i = 0; i < n; ++i) soa += bytes_of(expected[i].y());
  for (std::size_t i = 0; i < n; ++i) soa += bytes_of(static_cast<double>(expected[i].z()));

  const std::vector<std::pair<std::string, std::string>> files = {
      {"binary", records},
      {"binary_compressed", compressed_body(literal_only_lzf(soa), soa.size())},
      {"ascii", text}};
  for (const auto& [encoding, body] : files) {
    INFO(encoding);
    std::string contents = pcd_header(fields, sizes, types, counts, n, encoding) + body;
    io::CloudReadReport report;
    const model::PointCloud cloud = io::read_cloud(folder.write("f.pcd", contents), &report);
    CHECK(report.format == "pcd " + encoding);
    CHECK(report.ignored_fields == std::vector<std::string>{"rgb", "desc"});
    REQUIRE(cloud.size() == n);
    for (std::size_t i = 0; i < n; ++i) {
      // ascii went through std::to_string's six decimals.
      CHECK(cloud.points[i].isApprox(expected[i], 1e-3f));
    }
  }
}

TEST_CASE("a hand-made binary_compressed PCD reads back, NaN points dropped") {
  TempFolder folder;
  const std::vector<model::Point3f> points = {{1, 2, 3}, {kNaN, kNaN, kNaN}, {-4, 5.5f, 0.25f}};
  std::string soa;
  for (int axis = 0; axis < 3; ++axis) {
    for (const model::Point3f& p : points) soa += bytes_of(p[axis]);
  }
  const std::string contents = xyz_pcd_header(points.size(), "binary_compressed") +
                               compressed_body(literal_only_lzf(soa), soa.size());
  io::CloudReadReport report;
  const model::PointCloud cloud = io::read_cloud(folder.write("c.pcd", contents), &report);
  CHECK(report.format == "pcd binary_compressed");
  CHECK(report.points_in_file == 3);
  CHECK(report.dropped_non_finite == 1);
  REQUIRE(cloud.size() == 2);
  CHECK(cloud.points[0] == points[0]);
  CHECK(cloud.points[1] == points[2]);
}

TEST_CASE("LZF back-references repeat earlier output, overlapping runs included") {
  // Four points at (1, 1, 1): the 48 decompressed bytes are one float repeated. The stream
  // is a 4-byte literal, then one back-reference of 44 bytes from 4 bytes back. Its length
  // code 44 - 2 = 42 exceeds 6, so the control byte carries 7 (0xE0) and an extra byte the
  // remaining 35; the distance 4 is stored as 4 - 1 = 3.
  const std::string one = bytes_of(1.0f);
  const std::string stream = std::string(1, '\x03') + one + "\xE0\x23\x03";
  TempFolder folder;
  const std::string contents = xyz_pcd_header(4, "binary_compressed") + compressed_body(stream, 48);
  const model::PointCloud cloud = io::read_cloud(folder.write("r.pcd", contents));
  REQUIRE(cloud.size() == 4);
  for (const model::Point3f& p : cloud.points) CHECK(p == model::Point3f(1, 1, 1));
}

TEST_CASE("PLY elements before the vertices are skipped, extra properties ignored") {
  TempFolder folder;
  const std::string head =
      "ply\nformat %s 1.0\ncomment made by hand\nobj_info none\n"
      "element face 2\nproperty list uchar int vertex_indices\n"
      "element vertex 2\nproperty double x\nproperty float y\nproperty uchar red\n"
      "property float z\nproperty float nx\nend_header\n";
  const auto header_for = [&](const std::string& encoding) {
    std::string text = head;
    return text.replace(text.find("%s"), 2, encoding);
  };
  const std::string ascii = header_for("ascii") +
                            "3 0 1 2\n\n4 0 1 2 3\n1.5 2.5 255 3.5 0\n"
                            "-1 -2 0 -3 1\n";
  std::string binary = header_for("binary_little_endian");
  binary +=
      '\x03' + bytes_of(std::int32_t{0}) + bytes_of(std::int32_t{1}) + bytes_of(std::int32_t{2});
  binary += '\x01' + bytes_of(std::int32_t{0});
  binary += bytes_of(1.5) + bytes_of(2.5f) + '\xff' + bytes_of(3.5f) + bytes_of(0.0f);
  binary += bytes_of(-1.0) + bytes_of(-2.0f) + '\x00' + bytes_of(-3.0f) + bytes_of(1.0f);
  binary += "element faces follow here in some files";
  for (const std::string& contents : {ascii, binary}) {
    io::CloudReadReport report;
    const model::PointCloud cloud = io::read_cloud(folder.write("p.ply", contents), &report);
    INFO(report.format);
    CHECK(report.ignored_fields == std::vector<std::string>{"red", "nx"});
    REQUIRE(cloud.size() == 2);
    CHECK(cloud.points[0] == model::Point3f(1.5f, 2.5f, 3.5f));
    CHECK(cloud.points[1] == model::Point3f(-1, -2, -3));
    CHECK(cloud.origin == model::Point3f::Zero());
  }
}

TEST_CASE("PCL's real test clouds load with their documented finite point counts") {
  const std::string folder = std::string(RIGDESIGN_SOURCE_DIR) + "/../shared/data/real/";
  if (!std::filesystem::exists(folder + "office1.pcd")) {
    WARN("skipped: " << folder << " is absent");
    return;
  }
  struct RealCloud {
    const char* file;
    std::size_t finite_points;
    const char* colour_field;
  };
  const std::vector<RealCloud> clouds = {
      {"office1.pcd", 254456, "rgb"},
      {"five_people.pcd", 239075, "rgba"},
      {"table_scene_mug_stereo_textured.pcd", 209280, "rgba"},
      {"kinect_frame_20121214T142255.814212.pcd", 271575, "rgba"},
      {"milk_cartoon_all_small_clorox.pcd", 241407, "rgba"}};
  for (const RealCloud& real : clouds) {
    INFO(real.file);
    io::CloudReadReport report;
    const model::PointCloud cloud = io::read_cloud(folder + real.file, &report);
    CHECK(report.format == "pcd binary_compressed");
    CHECK(report.points_in_file == 307200);
    CHECK(cloud.size() == real.finite_points);
    CHECK(report.dropped_non_finite == 307200 - real.finite_points);
    CHECK(report.ignored_fields == std::vector<std::string>{real.colour_field});
    // A Kinect sees from 0.4 m to a few metres along its optical z axis.
    for (const model::Point3f& p : cloud.points) {
      if (!(p.z() > 0.0f && p.z() < 20.0f)) FAIL("implausible depth " << p.z());
    }
  }
  // office1's VIEWPOINT is "0 0 0 0 1 0 0": half a turn about x.
  const model::PointCloud office = io::read_cloud(folder + "office1.pcd");
  CHECK(office.orientation.coeffs().isApprox(Eigen::Vector4f(1, 0, 0, 0)));

  io::CloudReadReport report;
  const model::PointCloud map =
      io::read_cloud(folder + "subt_urban/urban_beta_both_floors_simplified.pcd", &report);
  CHECK(report.format == "pcd ascii");
  CHECK(map.size() == 47268);
  CHECK(report.dropped_non_finite == 0);
  CHECK(report.ignored_fields ==
        std::vector<std::string>{"rgb", "normal_x", "normal_y", "normal_z", "curvature"});
}

TEST_CASE("bad cloud files throw InputError naming file, place and field") {
  struct BadCase {
    const char* name;
    const char* file;
    std::string contents;
    std::string where;  // "file:line:col: field:" as the message starts, or "file: data:"
    std::string problem;
  };
  const std::string good = xyz_pcd_header(2, "ascii") + "1 2 3\n4 5 6\n";
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    return text.replace(text.find(from), from.size(), to);
  };
  const std::string ply_vertex = "element vertex 1\nproperty float x\nproperty float y\n";
  const std::string ply_head = "ply\nformat ascii 1.0\n" + ply_vertex + "property float z\n";
  const std::string binary_header = xyz_pcd_header(2, "binary");
  const std::vector<BadCase> cases = {
      {"unknown keyword", "a.pcd", edited("FIELDS", "FEILDS"), "a.pcd:3:1: header:", "'FEILDS'"},
      {"keyword twice", "a.pcd", edited("HEIGHT 1\n", "HEIGHT 1\nHEIGHT 1\n"),
       "a.pcd:9:1: HEIGHT:", "line 8"},
      {"missing keyword", "a.pcd", edited("POINTS 2\n", ""), "a.pcd:10:1: POINTS:", "no POINTS"},
      {"no DATA", "a.pcd", good.substr(0, good.find("DATA")), "a.pcd:10:1: DATA:", "DATA"},
      {"no z", "a.pcd", edited("FIELDS x y z", "FIELDS x y q"), "a.pcd:3:1: FIELDS:", "no field z"},
      {"SIZE too short", "a.pcd", edited("SIZE 4 4 4", "SIZE 4 4"),
       "a.pcd:4:1: SIZE:", "2 values for 3 FIELDS"},
      {"TYPE too long", "a.pcd", edited("TYPE F F F", "TYPE F F F F"),
       "a.pcd:5:1: TYPE:", "4 values"},
      {"COUNT too short", "a.pcd", edited("COUNT 1 1 1", "COUNT 1"),
       "a.pcd:6:1: COUNT:", "1 values"},
      {"integer x", "a.pcd", edited("TYPE F F F", "TYPE U F F"), "a.pcd:5:1: TYPE:", "field x"},
      {"impossible type", "a.pcd", edited("SIZE 4 4 4", "SIZE 2 4 4"),
       "a.pcd:5:1: TYPE:", "SIZE 2"},
      {"WIDTH x HEIGHT", "a.pcd", edited("HEIGHT 1", "HEIGHT 2"),
       "a.pcd:10:1: POINTS:", "differs from WIDTH 2 x HEIGHT 2"},
      {"bad encoding", "a.pcd", edited("DATA ascii", "DATA zip"), "a.pcd:11:1: DATA:", "'zip'"},
      {"bad viewpoint", "a.pcd", edited("VIEWPOINT 0 0 0 1 0 0 0", "VIEWPOINT 0 0 0 0 0 0 0"),
       "a.pcd:9:1: VIEWPOINT:", "quaternion is zero"},
      {"too few values", "a.pcd", edited("4 5 6", "4 5"),
       "a.pcd:13:1: data:", "point 1 has 2 values"},
      {"not a number", "a.pcd", edited("4 5 6", "4 five 6"),
       "a.pcd:13:1: data:", "y is 'five', not a number"},
      {"too few lines", "a.pcd", edited("4 5 6\n", ""), "a.pcd: data:", "after 1 of 2 points"},
      {"too many lines", "a.pcd", good + "7 8 9\n", "a.pcd:14:1: data:", "more lines"},
      {"truncated binary", "b.pcd", binary_header + std::string(20, '\0'),
       "b.pcd: data:", "20 bytes from byte offset " + std::to_string(binary_header.size())},
      {"compressed size beyond the file", "c.pcd",
       xyz_pcd_header(1, "binary_compressed") +
           compressed_body(literal_only_lzf("123456789012"), 12).substr(0, 15),
       "c.pcd: data:", "exceeds the 7 bytes left"},
      {"decompressed size not POINTS x record", "c.pcd",
       xyz_pcd_header(1, "binary_compressed") + compressed_body(literal_only_lzf("1234567890"), 10),
       "c.pcd: data:", "decompressed size 10"},
      {"corrupt LZF: reference before the start", "c.pcd",
       xyz_pcd_header(1, "binary_compressed") + compressed_body("\x20\x05", 12),
       "c.pcd: data:", "corrupt LZF stream"},
      {"corrupt LZF: literal past the end", "c.pcd",
       xyz_pcd_header(1, "binary_compressed") + compressed_body("\x0b"
                                                                "12345",
                                                                12),
       "c.pcd: data:", "passes the stream's end"},
      {"not PLY", "p.ply", "ply!\n" + ply_head.substr(4), "p.ply:1:1: ply:", "does not start"},
      {"PLY unknown keyword", "p.ply", ply_head + "1 2 3\n", "p.ply:7:1: header:", "'1'"},
      {"PLY without end_header", "p.ply", ply_head,
       "p.ply:6:1: end_header:", "without an end_header"},
      {"PLY without vertices", "p.ply",
       "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int v\nend_header\n",
       "p.ply:5:1: element vertex:", "no vertex element"},
      {"PLY big endian", "p.ply", "ply\nformat binary_big_endian 1.0\n",
       "p.ply:2:1: format:", "not supported"},
      {"PLY integer z", "p.ply",
       "ply\nformat ascii 1.0\n" + ply_vertex + "property int z\nend_header\n1 2 3\n",
       "p.ply:6:1: property:", "not float or double"},
      {"PLY without z", "p.ply", "ply\nformat ascii 1.0\n" + ply_vertex + "end_header\n",
       "p.ply:3:1: element vertex:", "no property z"},
      {"PLY truncated binary", "p.ply",
       "ply\nformat binary_little_endian 1.0\n" + ply_vertex + "property float z\nend_header\n" +
           std::string(11, '\0'),
       "p.ply: data:", "truncated in element vertex"},
      {"unknown extension", "a.las", good, "a.las: file:", ".pcd nor a .ply"},
  };
  TempFolder folder;
  for (const BadCase& bad : cases) {
    INFO(bad.name);
    const std::string path = folder.write(bad.file, bad.contents);
    try {
      io::read_cloud(path);
      FAIL("no InputError");
    } catch (const model::InputError& e) {
      const std::string message = e.what();
      INFO(message);
      CHECK(message.find(folder.path() + "/" + bad.where) == 0);
      CHECK(message.find(bad.problem) != std::string::npos);
    }
  }
}

TEST_CASE("a missing cloud file is an InputError naming it") {
  TempFolder folder;
  try {
    io::read_cloud(folder.path() + "/nowhere.pcd");
    FAIL("no InputError");
  } catch (const model::InputError& e) {
    CHECK(std::string(e.what()).find("nowhere.pcd: file: cannot be opened") != std::string::npos);
  }
}
