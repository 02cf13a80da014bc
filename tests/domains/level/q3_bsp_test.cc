// The Quake III map reader on real OpenArena maps, against a count written here from the
// format description (q3_test_support.h), and the .pk3 path against an extraction by unzip.
#include "sightline/domains/camera/level/q3_bsp.h"

#include <gtest/gtest.h>

#include "sightline/domains/camera/level/pk3_archive.h"
#include "sightline/domains/camera/level/q3_level.h"
#include "sightline/domains/camera/level/q3_patch.h"
#include "tests/domains/level/q3_test_support.h"

namespace sightline::camera {
namespace {

using namespace q3test;

// The maps extracted for this run (q3_test_support.h's scratch_dir) go when the tests end.
class RemoveScratchDir : public ::testing::Environment {
 public:
  void TearDown() override { std::filesystem::remove_all(scratch_dir()); }
};
[[maybe_unused]] ::testing::Environment* const kRemoveScratchDir =
    ::testing::AddGlobalTestEnvironment(new RemoveScratchDir);

// The scene frame of a Quake III map (FORMATS.md's defaults for .bsp and .pk3).
const LevelTransform kQuakeFrame{0.03125, UpAxis::kZ};

std::vector<unsigned char> map_bytes(const std::string& map, std::filesystem::path* path) {
  std::string why;
  *path = extract_map(map, &why);
  if (path->empty()) return {};
  return read_bytes(*path);
}

#define MAP_BYTES_OR_SKIP(map, bytes, path)                       \
  SKIP_WITHOUT_OPENARENA();                                       \
  std::filesystem::path path;                                     \
  const std::vector<unsigned char> bytes = map_bytes(map, &path); \
  if (bytes.empty()) GTEST_SKIP() << "cannot extract " << map << " without unzip or python3"

Eigen::Vector3d triangle_normal(const q3::Bsp& bsp, std::uint32_t t) {
  const auto& tri = bsp.triangles[t];
  const Eigen::Vector3d a = bsp.vertices[tri[0]].cast<double>();
  const Eigen::Vector3d b = bsp.vertices[tri[1]].cast<double>();
  const Eigen::Vector3d c = bsp.vertices[tri[2]].cast<double>();
  return (b - a).cross(c - a);
}

class Q3RealMap : public ::testing::TestWithParam<const char*> {};

TEST_P(Q3RealMap, TrianglesAndBoundsMatchACountMadeFromTheLumps) {
  MAP_BYTES_OR_SKIP(GetParam(), bytes, path);
  const q3::Bsp bsp = q3::parse_bsp(bytes, path.string());
  const IndependentCount expected = count_independently(bytes);
  ASSERT_GT(expected.triangles, 1000u);
  EXPECT_EQ(bsp.triangles.size(), expected.triangles);
  EXPECT_EQ(bsp.faces.size(), expected.kept_faces);
  std::size_t patch_triangles = 0;
  for (const auto& face : bsp.faces) {
    if (face.type == q3::FaceType::kPatch) patch_triangles += face.triangle_count;
  }
  EXPECT_EQ(patch_triangles, expected.patch_triangles);

  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  for (const auto& t : bsp.triangles) {
    for (std::uint32_t v : t) {
      ASSERT_LT(v, bsp.vertices.size());
      lo = lo.cwiseMin(bsp.vertices[v].cast<double>());
      hi = hi.cwiseMax(bsp.vertices[v].cast<double>());
    }
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(lo[k], expected.inner_min[k]) << k;
    EXPECT_GE(lo[k], expected.outer_min[k] - 1e-3) << k;
    EXPECT_GE(hi[k], expected.inner_max[k]) << k;
    EXPECT_LE(hi[k], expected.outer_max[k] + 1e-3) << k;
  }
}

TEST_P(Q3RealMap, PolygonTrianglesFaceWhereTheFileSaysTheFaceDoes) {
  MAP_BYTES_OR_SKIP(GetParam(), bytes, path);
  const q3::Bsp bsp = q3::parse_bsp(bytes, path.string());
  int agree = 0, disagree = 0;
  for (const auto& face : bsp.faces) {
    if (face.type != q3::FaceType::kPolygon) continue;
    // The face record's own normal (offset 84), as the map compiler wrote it.
    const Eigen::Vector3d normal =
        vec_at(bytes, lump_offset(bytes, kFacesLump) +
                          static_cast<std::size_t>(face.face) * kFaceBytes + 84);
    for (std::uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count;
         ++t) {
      // Slivers (q3map2 leaves some, less than 1/4 unit high, to fix T-junctions) have no
      // reliable direction in float: only triangles of some height are compared.
      const Eigen::Vector3d n = triangle_normal(bsp, t);
      const auto& tri = bsp.triangles[t];
      double longest = 0;
      for (int k = 0; k < 3; ++k) {
        longest = std::max(
            longest, (bsp.vertices[tri[k]] - bsp.vertices[tri[(k + 1) % 3]]).cast<double>().norm());
      }
      if (longest == 0 || n.norm() < 0.25 * longest) continue;
      (n.dot(normal) > 0 ? agree : disagree) += 1;
      if (n.dot(normal) <= 0 && disagree <= 5) {
        ADD_FAILURE() << "face " << face.face << " normal " << normal.transpose() << ", triangle "
                      << t << " faces " << n.transpose();
      }
    }
  }
  EXPECT_GT(agree, 100);
  EXPECT_EQ(disagree, 0);
}

TEST_P(Q3RealMap, PatchesFaceWhereTheirControlPointNormalsSay) {
  MAP_BYTES_OR_SKIP(GetParam(), bytes, path);
  if (count_independently(bytes).patch_triangles == 0) GTEST_SKIP() << "no drawn patches";
  const q3::Bsp bsp = q3::parse_bsp(bytes, path.string());
  int agree = 0, disagree = 0;
  for (const auto& face : bsp.faces) {
    if (face.type != q3::FaceType::kPatch) continue;
    const std::size_t at =
        lump_offset(bytes, kFacesLump) + static_cast<std::size_t>(face.face) * kFaceBytes;
    const auto first = static_cast<std::size_t>(le_i32(bytes, at + 12));
    const auto count = static_cast<std::size_t>(le_i32(bytes, at + 16));
    // The control points' normals (vertex offset 28), as the map compiler wrote them; some
    // maps hold garbage there (oa_thor's bevel patches): only sane normals are compared.
    Eigen::Vector3d file_normal = Eigen::Vector3d::Zero();
    bool sane = true;
    for (std::size_t v = first; v < first + count; ++v) {
      const Eigen::Vector3d n =
          vec_at(bytes, lump_offset(bytes, kVertexesLump) + v * kVertexBytes + 28);
      sane = sane && n.allFinite() && n.norm() <= 1.01;
      file_normal += n;
    }
    Eigen::Vector3d area = Eigen::Vector3d::Zero();
    for (std::uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count;
         ++t) {
      area += triangle_normal(bsp, t);
    }
    // A flat-folded or closed patch (a full pipe) has no net direction: clear cases only.
    if (!sane || area.norm() < 1 || file_normal.norm() < 0.5) continue;
    const double cosine = area.normalized().dot(file_normal.normalized());
    if (cosine > 0.3) ++agree;
    if (cosine < -0.3) ++disagree;
  }
  EXPECT_GE(agree, 10);
  EXPECT_EQ(disagree, 0);
}

// Straight down from each spawn point, the first triangle hit is a floor whose normal points
// up (+z): the winding the reader gives is the one TriangleMesh expects.
TEST_P(Q3RealMap, FloorsUnderTheSpawnPointsFaceUp) {
  MAP_BYTES_OR_SKIP(GetParam(), bytes, path);
  const q3::Bsp bsp = q3::parse_bsp(bytes, path.string());
  const auto spawns = spawn_points(bytes);
  ASSERT_GE(spawns.size(), 2u);
  for (const Eigen::Vector3d& s : spawns) {
    double best = 1e30;
    Eigen::Vector3d best_normal = Eigen::Vector3d::Zero();
    for (std::uint32_t t = 0; t < bsp.triangles.size(); ++t) {
      const auto& tri = bsp.triangles[t];
      const Eigen::Vector3d a = bsp.vertices[tri[0]].cast<double>();
      const Eigen::Vector3d b = bsp.vertices[tri[1]].cast<double>();
      const Eigen::Vector3d c = bsp.vertices[tri[2]].cast<double>();
      const Eigen::Vector3d n = (b - a).cross(c - a);
      if (std::abs(n.z()) < 1e-9) continue;
      // The vertical line through s meets the plane at z; inside when the 2-D edge signs agree.
      const double z = a.z() - (n.x() * (s.x() - a.x()) + n.y() * (s.y() - a.y())) / n.z();
      auto edge = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
        return (q.x() - p.x()) * (s.y() - p.y()) - (q.y() - p.y()) * (s.x() - p.x());
      };
      const double e0 = edge(a, b), e1 = edge(b, c), e2 = edge(c, a);
      const bool inside = (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
      if (inside && z <= s.z() && s.z() - z < best) best = s.z() - z, best_normal = n;
    }
    ASSERT_LT(best, 1e30) << "no floor under " << s.transpose();
    EXPECT_GT(best_normal.normalized().z(), 0.5) << "floor under " << s.transpose();
  }
}

TEST_P(Q3RealMap, Pk3AndTheExtractedBspGiveTheSameLevel) {
  MAP_BYTES_OR_SKIP(GetParam(), bytes, path);
  const std::string map = GetParam();
  const Level from_bsp = load_quake3_level({path.string(), "", {}, {}, {}}, kQuakeFrame);
  for (const std::string& name : {map, map + ".bsp", "maps/" + map + ".bsp"}) {
    const Level from_pk3 = load_quake3_level({kPak088, name, {}, {}, {}}, kQuakeFrame);
    EXPECT_EQ(from_pk3.map, map);
    EXPECT_EQ(from_pk3.format, "Quake III BSP (IBSP 46)");
    EXPECT_EQ(from_pk3.file, kPak088);
    ASSERT_EQ(from_pk3.mesh.vertices.size(), from_bsp.mesh.vertices.size());
    EXPECT_TRUE(from_pk3.mesh.vertices == from_bsp.mesh.vertices);
    EXPECT_TRUE(from_pk3.mesh.triangles == from_bsp.mesh.triangles);
    ASSERT_NE(from_pk3.solid, nullptr);
  }
  // And the scene frame is the file's, scaled by 1/32 with z up -> y up.
  const q3::Bsp bsp = q3::parse_bsp(bytes, path.string());
  ASSERT_EQ(from_bsp.mesh.vertices.size(), bsp.vertices.size());
  for (std::size_t v = 0; v < bsp.vertices.size(); v += 97) {
    const Eigen::Vector3f f = bsp.vertices[v];
    const Eigen::Vector3f expected(f.x() / 32, f.z() / 32, -f.y() / 32);
    EXPECT_LT((from_bsp.mesh.vertices[v] - expected).norm(), 1e-4f) << v;
  }
  EXPECT_EQ(from_bsp.map, "");
}

TEST_P(Q3RealMap, Pk3ArchiveReadsTheBytesUnzipExtracts) {
  MAP_BYTES_OR_SKIP(GetParam(), bytes, path);
  const Pk3Archive archive(kPak088);
  EXPECT_TRUE(archive.read("maps/" + std::string(GetParam()) + ".bsp") == bytes);
}

// aggressor: small, no patches; pxlfan: many drawn patches; oa_thor: the largest map, with
// patches of garbage normals, slivers and 11000 faces.
INSTANTIATE_TEST_SUITE_P(OpenArena, Q3RealMap, ::testing::Values("aggressor", "pxlfan", "oa_thor"));

TEST(Q3Bsp, EveryMapOfTheOpenArenaPaksParsesToTheIndependentCount) {
  SKIP_WITHOUT_OPENARENA();
  int maps = 0;
  for (const std::string pak : {"pak6-patch085.pk3", "pak6-patch088.pk3"}) {
    const std::string file = "/usr/share/games/openarena/baseoa/" + pak;
    if (!std::filesystem::exists(file)) continue;
    const Pk3Archive archive(file);
    for (const auto& entry : archive.map_entries()) {
      const auto bytes = archive.read(entry);
      const q3::Bsp bsp = q3::parse_bsp(bytes, file + " (" + entry + ")");
      EXPECT_GT(bsp.triangles.size(), 1000u) << entry;
      // Most of these maps hold -patchmeta's nodraw patch copies, some sky, water and fog.
      EXPECT_EQ(bsp.triangles.size(), count_independently(bytes).triangles) << entry;
      EXPECT_GT(bsp.counts.polygons + bsp.counts.meshes, 100) << entry;
      ++maps;
    }
  }
  EXPECT_GE(maps, 38);
}

TEST(Q3Patch, TessellationPassesThroughTheCornersAndCountsTriangles) {
  // A 5 x 3 patch: two sub-patches along u, a curved bump in the middle row.
  std::vector<Eigen::Vector3f> control;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 5; ++col) {
      control.emplace_back(static_cast<float>(col), static_cast<float>(row),
                           row == 1 && col == 2 ? 4.0f : 0.0f);
    }
  }
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  ASSERT_EQ(q3::patch_size_problem(5, 3, 15), nullptr);
  q3::tessellate_patch(control, 5, 3, vertices, triangles);
  EXPECT_EQ(static_cast<std::int64_t>(triangles.size()), q3::patch_triangle_count(5, 3));
  EXPECT_EQ(triangles.size(), 2u * 8 * 8 * 2);
  // Even-indexed control points lie on the surface: they are grid vertices, exactly.
  for (int row = 0; row < 3; row += 2) {
    for (int col = 0; col < 5; col += 2) {
      const Eigen::Vector3f c = control[static_cast<std::size_t>(row * 5 + col)];
      EXPECT_NE(std::find(vertices.begin(), vertices.end(), c), vertices.end()) << row << col;
    }
  }
  // The grid is 17 x 9 samples; its last one is the far corner control point (4, 2).
  EXPECT_EQ(vertices.back(), control.back());
  // Sample (column 4, row 4) is u = v = 1/2 in sub-patch 0, weights B(1/2) = (1/4, 1/2, 1/4):
  // x = 0/4 + 1/2 + 2/4 = 1, and the bump (row 1, column 2) weighs 1/2 * 1/4: z = 0.5.
  const Eigen::Vector3f mid = vertices[4 * 17 + 4];
  EXPECT_NEAR(mid.z(), 0.5f, 1e-6f);
  EXPECT_NEAR(mid.x(), 1.0f, 1e-6f);
  // Normals: a flat patch in z = 0 laid out with u along x, v along y faces +z.
  for (const auto& t : triangles) {
    const Eigen::Vector3f n =
        (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    EXPECT_GT(n.z(), 0) << "triangle faces down";
  }
}

TEST(Q3Patch, RefusesSizesThatAreNotPatches) {
  EXPECT_NE(q3::patch_size_problem(2, 3, 6), nullptr);
  EXPECT_NE(q3::patch_size_problem(3, 4, 12), nullptr);
  EXPECT_NE(q3::patch_size_problem(1, 1, 1), nullptr);
  EXPECT_NE(q3::patch_size_problem(3, 3, 10), nullptr);
  EXPECT_NE(q3::patch_size_problem(-3, -3, 9), nullptr);
  EXPECT_NE(q3::patch_size_problem(65537, 65537, 9), nullptr);
  EXPECT_EQ(q3::patch_size_problem(3, 5, 15), nullptr);
}

}  // namespace
}  // namespace sightline::camera
