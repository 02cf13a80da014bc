// Levels read through assimp (mesh_import.h) and the checks load_level (level.h) makes for
// every source. Each test writes its own small files (OBJ, glTF 2.0 .gltf and .glb, PLY,
// COLLADA) into a fresh folder and compares the loaded triangles with positions worked out
// here, by hand or with Eigen from the file's own numbers.
#include "sightline/domains/camera/level/mesh_import.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "sightline/domains/camera/level/level.h"

namespace sightline::camera {
namespace {

namespace fs = std::filesystem;
using Triangle = std::array<Eigen::Vector3d, 3>;

class MeshLevelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           (std::string("sightline_mesh_") + info->test_suite_name() + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) const {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    return path.string();
  }

  fs::path dir_;
};

LevelSpec spec_for(const std::string& file) {
  LevelSpec spec;
  spec.file = file;
  return spec;
}

std::vector<Triangle> triangles_of(const TriangleMesh& mesh) {
  std::vector<Triangle> out;
  for (std::uint32_t t = 0; t < mesh.size(); ++t)
    out.push_back({mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2)});
  return out;
}

// The same triangle with the same winding: equal corners up to a cyclic rotation.
bool same_triangle(const Triangle& a, const Triangle& b, double tolerance) {
  for (int r = 0; r < 3; ++r) {
    bool all = true;
    for (int i = 0; i < 3; ++i) all = all && (a[i] - b[(i + r) % 3]).norm() <= tolerance;
    if (all) return true;
  }
  return false;
}

// Every expected triangle matched by its own loaded triangle, and nothing more.
void expect_same_triangles(const TriangleMesh& mesh, const std::vector<Triangle>& expected,
                           double tolerance = 1e-5) {
  const auto actual = triangles_of(mesh);
  ASSERT_EQ(actual.size(), expected.size());
  std::vector<bool> used(actual.size(), false);
  for (const auto& want : expected) {
    bool found = false;
    for (std::size_t i = 0; i < actual.size() && !found; ++i) {
      if (!used[i] && same_triangle(actual[i], want, tolerance)) used[i] = found = true;
    }
    EXPECT_TRUE(found) << "no loaded triangle (" << want[0].transpose() << ") ("
                       << want[1].transpose() << ") (" << want[2].transpose() << ")";
  }
}

// An InputError whose message names `file` and contains `expected`.
void expect_input_error(const std::function<void()>& load, const std::string& file,
                        const std::string& expected) {
  try {
    load();
    ADD_FAILURE() << "no error for " << file;
  } catch (const csp::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'" + file + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }
}

// --- glTF 2.0 ----------------------------------------------------------------------------

std::string base64(const std::string& bytes) {
  static const char* const kAlphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
    out += kAlphabet[(n >> 18) & 63];
    out += kAlphabet[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[n & 63] : '=';
  }
  return out;
}

template <class T>
void append_le(std::string& bytes, T value) {
  const auto* p =
      reinterpret_cast<const char*>(&value);  // x86-64 and the glTF buffer: little-endian
  bytes.append(p, sizeof value);
}

// The one mesh of the glTF files: the triangle (0,0,0) (1,0,0) (0,1,0), indexed.
const std::vector<Eigen::Vector3d> kGltfTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

std::string gltf_buffer() {
  std::string bytes;
  for (const auto& p : kGltfTriangle) {
    for (int i = 0; i < 3; ++i) append_le(bytes, static_cast<float>(p[i]));
  }
  for (std::uint16_t i : {0, 1, 2, 0}) append_le(bytes, i);  // the last one pads to 4 bytes
  return bytes;
}

// A glTF document with `nodes` (a JSON array) over the one mesh; `buffer_uri` empty for .glb.
std::string gltf_json(const std::string& nodes, const std::string& buffer_uri) {
  const std::string uri = buffer_uri.empty() ? "" : R"("uri": ")" + buffer_uri + R"(", )";
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": )" +
         nodes + R"(,
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
    "buffers": [{)" +
         uri + R"("byteLength": 44}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                    {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
}

std::string gltf_text(const std::string& nodes) {
  return gltf_json(nodes, "data:application/octet-stream;base64," + base64(gltf_buffer()));
}

// GLB: a 12-byte header, then a JSON chunk and a BIN chunk, each 4-byte aligned.
std::string glb(const std::string& nodes) {
  std::string json = gltf_json(nodes, "");
  while (json.size() % 4 != 0) json += ' ';
  std::string bin = gltf_buffer();
  while (bin.size() % 4 != 0) bin += '\0';
  std::string out = "glTF";
  append_le(out, std::uint32_t{2});
  append_le(out, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  append_le(out, static_cast<std::uint32_t>(json.size()));
  out += "JSON" + json;
  append_le(out, static_cast<std::uint32_t>(bin.size()));
  out += std::string("BIN\0", 4) + bin;
  return out;
}

// Parent: translation (10,0,0), 90 degrees about +y, scale 2. Children, both the same mesh:
// A translated by (0,1,0); B with translation (0,0,5), 90 degrees about +x, scale (3,1,1).
const char* const kHierarchy = R"([
  {"name": "parent", "translation": [10, 0, 0], "rotation": [0, 0.70710678, 0, 0.70710678],
   "scale": [2, 2, 2], "children": [1, 2]},
  {"name": "a", "mesh": 0, "translation": [0, 1, 0]},
  {"name": "b", "mesh": 0, "translation": [0, 0, 5], "rotation": [0.70710678, 0, 0, 0.70710678],
   "scale": [3, 1, 1]}])";

// Worked out by hand: a node maps q to T + R (S q); 90 degrees about +y maps (x,y,z) to
// (z,y,-x), about +x to (x,-z,y). A: (0,0,0) -> (0,1,0) -> (0,2,0) -> (0,2,0) -> (10,2,0) ...
const std::vector<Triangle> kHierarchyTriangles = {
    {Eigen::Vector3d(10, 2, 0), Eigen::Vector3d(10, 2, -2), Eigen::Vector3d(10, 4, 0)},
    {Eigen::Vector3d(20, 0, 0), Eigen::Vector3d(20, 0, -6), Eigen::Vector3d(22, 0, 0)}};

TEST_F(MeshLevelTest, ObjQuadIsTriangulatedIntoTwoTrianglesOverItsCorners) {
  const std::string file = write("quad.obj", "v 1 2 3\nv 4 2 3\nv 4 2 7\nv 1 2 7\nf 1 2 3 4\n");
  const Level level = load_level(spec_for(file));
  ASSERT_EQ(level.mesh.size(), 2u);
  const Eigen::Vector3d corners[] = {{1, 2, 3}, {4, 2, 3}, {4, 2, 7}, {1, 2, 7}};
  const Eigen::Vector3d quad_normal =
      (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  double area = 0;
  for (const auto& t : triangles_of(level.mesh)) {
    for (const auto& p : t) {
      bool corner = false;
      for (const auto& c : corners) corner = corner || (p - c).norm() < 1e-6;
      EXPECT_TRUE(corner) << p.transpose();
    }
    const Eigen::Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]);
    EXPECT_NEAR(n.normalized().dot(quad_normal), 1.0, 1e-9);  // the file's winding is kept
    area += n.norm() / 2;
  }
  EXPECT_NEAR(area, 3.0 * 4.0, 1e-9);  // the two halves cover the quad without overlap
  EXPECT_NE(level.format.find("Wavefront"), std::string::npos) << level.format;
  EXPECT_NE(level.format.find("(assimp)"), std::string::npos) << level.format;
}

TEST_F(MeshLevelTest, ObjTrianglesKeepTheirVerticesAndWinding) {
  const std::string file =
      write("two.obj", "v 0 0 0\nv 2 0 0\nv 0 3 0\nv 5 5 5\nv 6 5 5\nv 5 5 4\nf 1 2 3\nf 4 6 5\n");
  const Level level = load_mesh_level(spec_for(file), LevelTransform{});
  expect_same_triangles(
      level.mesh, {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 3, 0)},
                   {Eigen::Vector3d(5, 5, 5), Eigen::Vector3d(5, 5, 4), Eigen::Vector3d(6, 5, 5)}});
}

TEST_F(MeshLevelTest, GltfNodeTransformsAreComposedDownTheHierarchyAndEachInstanceIsPlaced) {
  const std::string file = write("hierarchy.gltf", gltf_text(kHierarchy));
  const Level level = load_level(spec_for(file));
  expect_same_triangles(level.mesh, kHierarchyTriangles);
  EXPECT_NE(level.format.find("glTF2"), std::string::npos) << level.format;
}

TEST_F(MeshLevelTest, GltfWithArbitraryTransformsMatchesEigenComposition) {
  // A child given as a column-major matrix, under a parent with an oblique rotation and a
  // non-uniform scale, under a translated root: three levels, checked against Eigen.
  const Eigen::Quaterniond q =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  Eigen::Affine3d child = Eigen::Translation3d(-1, 0.5, 2) *
                          Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitZ()) *
                          Eigen::Scaling(0.5, 1.5, 1.0);
  std::string matrix = "[";
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r)
      matrix += std::to_string(child.matrix()(r, c)) + (r == 3 && c == 3 ? "]" : ", ");
  }
  const std::string nodes = R"([{"translation": [0, -3, 4], "children": [1]},
    {"rotation": [)" + std::to_string(q.x()) +
                            ", " + std::to_string(q.y()) + ", " + std::to_string(q.z()) + ", " +
                            std::to_string(q.w()) + R"(], "scale": [1, 2, 0.5], "children": [2]},
    {"mesh": 0, "matrix": )" +
                            matrix + "}]";
  const std::string file = write("deep.gltf", gltf_text(nodes));
  // The matrix as written (to_string keeps six decimals), so the comparison is exact up to float.
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r)
      child.matrix()(r, c) = std::stod(std::to_string(child.matrix()(r, c)));
  }
  const Eigen::Quaterniond written(
      std::stod(std::to_string(q.w())), std::stod(std::to_string(q.x())),
      std::stod(std::to_string(q.y())), std::stod(std::to_string(q.z())));
  const Eigen::Affine3d global =
      Eigen::Translation3d(0, -3, 4) * written.normalized() * Eigen::Scaling(1.0, 2.0, 0.5) * child;
  Triangle expected;
  for (int i = 0; i < 3; ++i) expected[i] = global * kGltfTriangle[i];
  expect_same_triangles(load_level(spec_for(file)).mesh, {expected}, 1e-4);
}

TEST_F(MeshLevelTest, MirroringNodeKeepsTheFrontOfItsTriangles) {
  // Scale -1 along x mirrors the triangle (front +z) to (0,0,0) (-1,0,0) (0,1,0); its front
  // still faces +z, so the corners come out in the order that makes the normal +z again.
  const std::string file = write("mirror.gltf", gltf_text(R"([{"mesh": 0, "scale": [-1, 1, 1]}])"));
  const TriangleMesh mesh = load_level(spec_for(file)).mesh;
  expect_same_triangles(
      mesh, {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(-1, 0, 0)}});
  const Triangle t = triangles_of(mesh)[0];
  EXPECT_GT((t[1] - t[0]).cross(t[2] - t[0]).z(), 0);
}

TEST_F(MeshLevelTest, GlbBinaryReadsLikeTheTextForm) {
  const std::string file = write("hierarchy.glb", glb(kHierarchy));
  const Level level = load_level(spec_for(file));
  expect_same_triangles(level.mesh, kHierarchyTriangles);
  EXPECT_NE(level.format.find("glTF2"), std::string::npos) << level.format;
}

TEST_F(MeshLevelTest, GltfBufferInAFileBesideItIsFound) {
  write("tri.bin", gltf_buffer());
  const std::string file = write("external.gltf", gltf_json(kHierarchy, "tri.bin"));
  expect_same_triangles(load_level(spec_for(file)).mesh, kHierarchyTriangles);
  fs::remove(dir_ / "tri.bin");  // and a missing buffer file is assimp's error, not a crash
  expect_input_error([&] { load_level(spec_for(file)); }, file, "assimp");
}

TEST_F(MeshLevelTest, ScaleAndUpZMapXYZToScaledXZMinusY) {
  const std::string file = write("tri.obj", "v 1 2 3\nv -4 5 6\nv 7 -8 9\nf 1 2 3\n");
  LevelSpec spec = spec_for(file);
  spec.scale = 0.5;
  spec.up = UpAxis::kZ;
  const Level level = load_level(spec);
  EXPECT_EQ(level.transform.scale, 0.5);
  EXPECT_EQ(level.transform.up, UpAxis::kZ);
  expect_same_triangles(level.mesh, {{Eigen::Vector3d(0.5, 1.5, -1), Eigen::Vector3d(-2, 3, -2.5),
                                      Eigen::Vector3d(3.5, 4.5, 4)}});
  spec.up = UpAxis::kY;
  expect_same_triangles(
      load_level(spec).mesh,
      {{Eigen::Vector3d(0.5, 1, 1.5), Eigen::Vector3d(-2, 2.5, 3), Eigen::Vector3d(3.5, -4, 4.5)}});
}

TEST_F(MeshLevelTest, PlyGoesToAssimpWithScaleOneAndYUpByDefault) {
  const std::string file =
      write("tri.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n1 2 3\n4 2 3\n1 2 9\n3 0 1 2\n");
  const Level level = load_level(spec_for(file));
  EXPECT_EQ(level.file, file);
  EXPECT_EQ(level.transform.scale, 1.0);
  EXPECT_EQ(level.transform.up, UpAxis::kY);
  EXPECT_EQ(level.solid, nullptr);
  EXPECT_TRUE(level.map.empty());
  EXPECT_GE(level.load_seconds, 0.0);
  EXPECT_NE(level.format.find("PLY"), std::string::npos) << level.format;
  expect_same_triangles(
      level.mesh, {{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 2, 3), Eigen::Vector3d(1, 2, 9)}});
}

TEST_F(MeshLevelTest, ColladaUnitAndUpAxisAreAppliedByAssimpItself) {
  // A COLLADA file states its unit and up axis; assimp applies both (as a root transform),
  // so such a level keeps the defaults (scale 1, up y) and still comes out in metres, y up.
  const std::string file = write("tri.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="centimeter" meter="0.01"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries><geometry id="tri"><mesh>
    <source id="pos"><float_array id="pos-array" count="9">0 0 0 100 0 0 0 100 200</float_array>
      <technique_common><accessor source="#pos-array" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="verts"><input semantic="POSITION" source="#pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#verts" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="n"><instance_geometry url="#tri"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)");
  const Level level = load_level(spec_for(file));
  EXPECT_NE(level.format.find("Collada"), std::string::npos) << level.format;
  expect_same_triangles(level.mesh, {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                      Eigen::Vector3d(0, 2, -1)}});
}

TEST(IsQuake3Level, BspAndPk3InAnyCaseAndNothingElse) {
  EXPECT_TRUE(is_quake3_level("maps/q3dm1.bsp"));
  EXPECT_TRUE(is_quake3_level("/x/y/pak0.PK3"));
  EXPECT_TRUE(is_quake3_level("a.Bsp"));
  EXPECT_FALSE(is_quake3_level("a.bsp.obj"));
  EXPECT_FALSE(is_quake3_level("bsp"));
  EXPECT_FALSE(is_quake3_level("level.glb"));
  EXPECT_FALSE(is_quake3_level("pk3/level.gltf"));
}

TEST(UpAxis, ReadsYAndZOnlyAndWritesThemBack) {
  EXPECT_EQ(up_axis_from_string("y"), UpAxis::kY);
  EXPECT_EQ(up_axis_from_string("z"), UpAxis::kZ);
  for (const char* bad : {"", "x", "Y", "Z", "-z", "zz", "y "})
    EXPECT_FALSE(up_axis_from_string(bad)) << bad;
  EXPECT_STREQ(to_string(UpAxis::kY), "y");
  EXPECT_STREQ(to_string(UpAxis::kZ), "z");
}

// --- bad input ---------------------------------------------------------------------------

TEST_F(MeshLevelTest, MissingFileIsReportedAtTheScenesLevelLine) {
  LevelSpec spec = spec_for((dir_ / "nowhere.obj").string());
  spec.where = {"scenes/atrium.yaml", 12, 0};
  try {
    load_level(spec);
    FAIL() << "no error";
  } catch (const csp::InputError& error) {
    EXPECT_EQ(error.where().file, "scenes/atrium.yaml");
    EXPECT_EQ(error.where().line, 12);
    EXPECT_EQ(std::string(error.what()),
              "scenes/atrium.yaml:12: level file '" + spec.file + "' does not exist");
  }
  spec.where = {};  // not from a scene: the level file itself is the location
  expect_input_error([&] { load_level(spec); }, spec.file, "does not exist");
  spec.file = dir_.string();
  expect_input_error([&] { load_level(spec); }, spec.file, "is a directory");
  spec.file =
      (dir_ / "nowhere.obj").string();  // the assimp branch alone, without the existence check
  expect_input_error([&] { load_mesh_level(spec, LevelTransform{}); }, spec.file, "assimp");
}

TEST_F(MeshLevelTest, FilesAssimpCannotReadGiveItsReason) {
  std::string garbage;
  for (int i = 0; i < 300; ++i) garbage += static_cast<char>((i * 7919 + 13) % 256);
  for (const char* name :
       {"garbage.obj", "garbage.glb", "garbage.gltf", "garbage.ply", "garbage.xyz"}) {
    const std::string file = write(name, garbage);
    expect_input_error([&] { load_level(spec_for(file)); }, file, "assimp");
  }
  const std::string truncated_glb = glb(kHierarchy).substr(0, 60);
  const std::string file = write("truncated.glb", truncated_glb);
  expect_input_error([&] { load_level(spec_for(file)); }, file, "assimp");
}

TEST_F(MeshLevelTest, NanOrInfiniteVertexNamesTheVertex) {
  for (const char* value : {"nan", "-nan", "inf", "-inf"}) {
    const std::string file =
        write("bad.obj", std::string("v 0 0 0\nv ") + value + " 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_input_error([&] { load_level(spec_for(file)); }, file, "vertex 1 of 3");
    expect_input_error([&] { load_level(spec_for(file)); }, file, "not a finite number");
  }
}

TEST_F(MeshLevelTest, ScaleThatOverflowsFloatIsReported) {
  const std::string file = write("big.obj", "v 0 0 0\nv 1e30 0 0\nv 0 1 0\nf 1 2 3\n");
  LevelSpec spec = spec_for(file);
  spec.scale = 1e10;
  expect_input_error([&] { load_level(spec); }, file, "vertex 1 of 3");
}

TEST_F(MeshLevelTest, ScaleMustBeFiniteAndPositive) {
  const std::string file = write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (double scale : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                       std::numeric_limits<double>::infinity()}) {
    LevelSpec spec = spec_for(file);
    spec.scale = scale;
    expect_input_error([&] { load_level(spec); }, file, "scale");
  }
}

TEST_F(MeshLevelTest, PointsLinesAndEmptyFilesHaveNoSolidTriangles) {
  const std::string lines = write("lines.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2\nl 2 3\np 3\n");
  expect_input_error([&] { load_level(spec_for(lines)); }, lines,
                     "has no solid triangles, only 3 points and lines");
  const std::string points =
      write("points.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
  expect_input_error([&] { load_level(spec_for(points)); }, points,
                     "has no solid triangles: its meshes hold vertices but no faces");
  // Comments only: assimp reads no mesh at all (with fewer than 16 bytes its OBJ reader
  // refuses the file outright, which says so too).
  const std::string comments =
      write("comments.obj", "# nothing here\n# only comments, no geometry at all\n");
  expect_input_error([&] { load_level(spec_for(comments)); }, comments,
                     "holds no mesh, so no solid triangles");
  const std::string empty = write("empty.obj", "");
  expect_input_error([&] { load_level(spec_for(empty)); }, empty, "could not be read by assimp");
}

TEST_F(MeshLevelTest, ZeroAreaTrianglesAreDroppedAndALevelOfOnlyThoseIsRejected) {
  // Collinear corners, and a triangle whose corners are one point.
  const std::string flat =
      write("flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 5 5 5\nf 1 2 3\nf 4 4 4\n");
  expect_input_error([&] { load_level(spec_for(flat)); }, flat,
                     "has no solid triangles (all 2 triangles have zero area)");
  const std::string mixed = write(
      "mixed.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nv 0 0 1\nv 1 0 1\nv 0 1 1\nf 1 2 3\nf 4 5 6\n");
  expect_same_triangles(
      load_level(spec_for(mixed)).mesh,
      {{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), Eigen::Vector3d(0, 1, 1)}});
}

}  // namespace
}  // namespace sightline::camera
