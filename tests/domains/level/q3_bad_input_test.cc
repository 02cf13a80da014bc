// Bad Quake III input: missing files, unknown maps, broken archives, and a real map's bytes
// with one field corrupted at a time. Each must be a csp::InputError naming the file, with a
// message saying what is wrong; never a crash (the fuzzer in fuzz/ covers the rest).
#include <gtest/gtest.h>

#include <cmath>

#include "sightline/domains/camera/level/pk3_archive.h"
#include "sightline/domains/camera/level/q3_bsp.h"
#include "sightline/domains/camera/level/q3_level.h"
#include "tests/domains/level/q3_test_support.h"

namespace sightline::camera {
namespace {

using namespace q3test;

const LevelTransform kQuakeFrame{0.03125, UpAxis::kZ};

// The InputError that loading `spec` throws (fails the test when none is thrown).
csp::InputError load_error(const LevelSpec& spec) {
  try {
    load_quake3_level(spec, kQuakeFrame);
  } catch (const csp::InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError for " << spec.file << " " << spec.map;
  return csp::InputError({}, "");
}

std::string parse_error(const std::vector<unsigned char>& bytes) {
  try {
    q3::parse_bsp(bytes, "corrupt.bsp");
  } catch (const csp::InputError& e) {
    EXPECT_EQ(e.where().file, "corrupt.bsp");
    return e.detail();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

TEST(Q3BadInput, AMissingFileIsAnInputErrorNamingIt) {
  for (const std::string file : {"/nonexistent/dir/none.bsp", "/nonexistent/dir/none.pk3"}) {
    const auto e = load_error({file, "", {}, {}, {}});
    EXPECT_EQ(e.where().file, file);
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos) << e.what();
  }
}

TEST(Q3BadInput, AnUnknownMapListsTheMapsTheArchiveHolds) {
  SKIP_WITHOUT_OPENARENA();
  const auto e = load_error({kPak088, "oa_nosuchmap", {}, {}, {}});
  EXPECT_EQ(e.where().file, kPak088);
  const std::string message = e.what();
  for (const char* map : {"oa_nosuchmap", "aggressor", "oa_thor", "slimefac"}) {
    EXPECT_NE(message.find(map), std::string::npos) << message;
  }
  EXPECT_EQ(message.find("maps/aggressor.bsp"), std::string::npos) << "lists names: " << message;
}

TEST(Q3BadInput, AnArchiveOfSeveralMapsNeedsAMap) {
  SKIP_WITHOUT_OPENARENA();
  const auto e = load_error({kPak088, "", {}, {}, {}});
  EXPECT_EQ(e.where().file, kPak088);
  EXPECT_NE(e.detail().find("`map`"), std::string::npos) << e.what();
  EXPECT_NE(e.detail().find("oa_thor"), std::string::npos) << e.what();
}

TEST(Q3BadInput, AFileThatIsNotAZipIsRefusedAsAPk3) {
  const auto file = (scratch_dir() / "text.pk3").string();
  write_bytes(file, {'h', 'e', 'l', 'l', 'o', '\n'});
  const auto e = load_error({file, "", {}, {}, {}});
  EXPECT_EQ(e.where().file, file);
  EXPECT_NE(e.detail().find("not a zip"), std::string::npos) << e.what();
}

// A zip written by python3's zipfile (stored, not deflated, so a byte is easy to flip).
std::string python_zip(const std::string& name, const std::string& entry, const std::string& data) {
  const auto file = (scratch_dir() / name).string();
  const std::string command = "python3 -c \"import zipfile; z = zipfile.ZipFile('" + file +
                              "', 'w'); z.writestr('" + entry + "', '" + data + "'); z.close()\"";
  return std::system(command.c_str()) == 0 ? file : "";
}

TEST(Q3BadInput, ACorruptArchiveEntryIsRefused) {
  if (!have_program("python3")) GTEST_SKIP() << "python3 is needed to write the test zip";
  const std::string file = python_zip("crc.pk3", "maps/one.bsp", "IBSP-and-some-bytes");
  ASSERT_FALSE(file.empty());
  auto bytes = read_bytes(file);
  // Flip one byte of the stored data (found by its text) so the CRC no longer matches.
  const std::string text(bytes.begin(), bytes.end());
  const auto at = text.find("IBSP-and");
  ASSERT_NE(at, std::string::npos);
  bytes[at + 5] ^= 0x20;
  write_bytes(file, bytes);
  const auto e = load_error({file, "one", {}, {}, {}});
  EXPECT_EQ(e.where().file, file);
  EXPECT_NE(e.detail().find("corrupt"), std::string::npos) << e.what();
}

TEST(Q3BadInput, AnArchiveWithoutMapsOrWithABrokenMapIsRefused) {
  if (!have_program("python3")) GTEST_SKIP() << "python3 is needed to write the test zip";
  const std::string empty = python_zip("nomaps.pk3", "scripts/a.shader", "x");
  ASSERT_FALSE(empty.empty());
  EXPECT_NE(load_error({empty, "", {}, {}, {}}).detail().find("no map"), std::string::npos);
  const std::string broken = python_zip("broken.pk3", "maps/tiny.bsp", "IBSP");
  ASSERT_FALSE(broken.empty());
  const auto e = load_error({broken, "", {}, {}, {}});  // the only map: no `map` needed
  EXPECT_NE(std::string(e.what()).find(broken), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("maps/tiny.bsp"), std::string::npos) << e.what();
  EXPECT_NE(e.detail().find("truncated"), std::string::npos) << e.what();
}

// --- One field of a real map corrupted at a time. ---

class Q3CorruptMap : public ::testing::Test {
 protected:
  // aggressor: small; patch tests use pxlfan (aggressor has no patches).
  virtual const char* map() const { return "aggressor"; }
  void SetUp() override {
    SKIP_WITHOUT_OPENARENA();
    std::string why;
    path_ = extract_map(map(), &why);
    if (path_.empty()) GTEST_SKIP() << why;
    good_ = read_bytes(path_);
    ASSERT_NO_THROW(q3::parse_bsp(good_, "good.bsp"));
  }
  std::size_t record(int lump, std::size_t size, std::size_t index) const {
    return lump_offset(good_, lump) + size * index;
  }
  std::size_t count(int lump, std::size_t size) const { return lump_length(good_, lump) / size; }
  // The first face of `type` (1 polygon, 2 patch, 3 mesh).
  std::size_t first_face(std::int32_t type) const {
    for (std::size_t f = 0; f < count(kFacesLump, kFaceBytes); ++f) {
      if (le_i32(good_, record(kFacesLump, kFaceBytes, f) + 8) == type) return f;
    }
    ADD_FAILURE() << "no face of type " << type << " in " << map();
    return 0;
  }
  // A copy with the int at `at` set to `value`; the message must contain `expected`.
  void expect_refused(std::size_t at, std::int32_t value, const std::string& expected) const {
    auto bytes = good_;
    put_i32(bytes, at, value);
    const std::string message = parse_error(bytes);
    EXPECT_NE(message.find(expected), std::string::npos) << message;
  }

  std::filesystem::path path_;
  std::vector<unsigned char> good_;
};

TEST_F(Q3CorruptMap, ATruncatedFileIsRefusedWherever) {
  for (std::size_t size : {std::size_t{0}, std::size_t{3}, std::size_t{143}, std::size_t{144},
                           good_.size() / 2, good_.size() - 1}) {
    const std::vector<unsigned char> cut(good_.begin(), good_.begin() + static_cast<long>(size));
    const std::string message = parse_error(cut);
    EXPECT_TRUE(message.find("truncated") != std::string::npos ||
                message.find("not inside the file") != std::string::npos)
        << size << ": " << message;
  }
  // And from a file on disk, through the loader: the error names that file.
  const auto file = (scratch_dir() / "cut.bsp").string();
  write_bytes(file, std::vector<unsigned char>(good_.begin(), good_.begin() + 5000));
  EXPECT_EQ(load_error({file, "", {}, {}, {}}).where().file, file);
}

TEST_F(Q3CorruptMap, WrongMagicOrVersionIsRefused) {
  auto bytes = good_;
  bytes[0] = 'V';
  EXPECT_NE(parse_error(bytes).find("IBSP"), std::string::npos);
  expect_refused(4, 47, "version 47");
  expect_refused(4, 38, "version 38");
}

TEST_F(Q3CorruptMap, ALumpOutsideTheFileIsRefused) {
  const std::size_t faces = 8 + 8 * kFacesLump;
  expect_refused(faces, static_cast<std::int32_t>(good_.size()), "lump faces");
  expect_refused(faces, -104, "lump faces");
  expect_refused(faces + 4, 0x7ffffff8, "not inside the file");
  expect_refused(8 + 8 * kPlanesLump + 4, -16, "lump planes");
}

TEST_F(Q3CorruptMap, ALumpLengthThatIsNotWholeRecordsIsRefused) {
  expect_refused(8 + 8 * kFacesLump + 4,
                 static_cast<std::int32_t>(lump_length(good_, kFacesLump) - 1),
                 "not a multiple of its 104-byte records");
  expect_refused(8 + 8 * kVertexesLump + 4,
                 static_cast<std::int32_t>(lump_length(good_, kVertexesLump) - 4), "44-byte");
}

TEST_F(Q3CorruptMap, AnIndexOutOfRangeIsRefused) {
  const auto faces = static_cast<std::int32_t>(count(kFacesLump, kFaceBytes));
  const auto shaders = static_cast<std::int32_t>(count(kShadersLump, kShaderBytes));
  const auto vertexes = static_cast<std::int32_t>(count(kVertexesLump, kVertexBytes));
  const auto meshverts = static_cast<std::int32_t>(count(kMeshVertsLump, 4));
  const auto planes = static_cast<std::int32_t>(count(kPlanesLump, 16));
  const auto nodes = static_cast<std::int32_t>(count(kNodesLump, 36));
  const auto leaves = static_cast<std::int32_t>(count(kLeavesLump, 48));
  const auto brushes = static_cast<std::int32_t>(count(kBrushesLump, 12));
  const auto sides = static_cast<std::int32_t>(count(kBrushSidesLump, 8));
  const auto leafbrushes = static_cast<std::int32_t>(count(kLeafBrushesLump, 4));
  ASSERT_GT(faces, 0);
  const std::size_t polygon = record(kFacesLump, kFaceBytes, first_face(1));
  expect_refused(polygon, shaders, "shader " + std::to_string(shaders) + " out of range");
  expect_refused(polygon, -1, "shader -1 out of range");
  expect_refused(polygon + 12, vertexes, "vertices");
  expect_refused(polygon + 16, 0x7fffffff, "vertices");  // first + count would overflow int32
  expect_refused(polygon + 20, meshverts - 1, "meshverts");
  expect_refused(polygon + 24, 4, "not a whole number of triangles");
  expect_refused(polygon + 8, 9, "unknown face type 9");
  // A meshvert of the polygon pointing past the polygon's vertices.
  const auto first_meshvert = static_cast<std::size_t>(le_i32(good_, polygon + 20));
  expect_refused(record(kMeshVertsLump, 4, first_meshvert), le_i32(good_, polygon + 16),
                 "vertex offset");
  expect_refused(record(kNodesLump, 36, 0), planes, "node 0: plane");
  expect_refused(record(kNodesLump, 36, 0) + 4, 0, "child node 0");  // a cycle on itself
  expect_refused(record(kNodesLump, 36, 1) + 8, nodes, "child node");
  expect_refused(record(kNodesLump, 36, 0) + 8, -(leaves + 1), "leaf");
  expect_refused(record(kLeavesLump, 48, 1) + 40, leafbrushes + 1, "leafbrushes");
  expect_refused(record(kLeavesLump, 48, 1) + 44, -1, "leafbrushes");
  expect_refused(record(kLeafBrushesLump, 4, 0), brushes, "brush");
  expect_refused(record(kBrushesLump, 12, 0), sides, "brushsides");
  expect_refused(record(kBrushesLump, 12, 0) + 8, shaders, "shader");
  expect_refused(record(kBrushSidesLump, 8, 0), planes, "plane");
  expect_refused(record(kBrushSidesLump, 8, 0) + 4, -5, "shader");
}

class Q3CorruptPatchMap : public Q3CorruptMap {
  const char* map() const override { return "pxlfan"; }
};

TEST_F(Q3CorruptPatchMap, APatchOfImpossibleSizeIsRefused) {
  const std::size_t patch = record(kFacesLump, kFaceBytes, first_face(2));
  expect_refused(patch + 96, 4, "must be odd");
  expect_refused(patch + 96, 1, "at least 3 x 3");
  expect_refused(patch + 100, 0x7fffffff, "differs from its number");
  expect_refused(patch + 16, le_i32(good_, patch + 16) + 1, "differs from its number");
}

TEST_F(Q3CorruptMap, NonFiniteCoordinatesAreRefused) {
  const auto nan = static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(std::nanf("")));
  const auto inf = static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(INFINITY));
  expect_refused(record(kVertexesLump, kVertexBytes, 3) + 4, nan, "vertex 3");
  expect_refused(record(kVertexesLump, kVertexBytes, 3) + 8, inf, "not a finite number");
  expect_refused(record(kPlanesLump, 16, 2) + 12, nan, "plane 2");
}

}  // namespace
}  // namespace sightline::camera
