#include "sightline/domains/camera/level/q3_bsp.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "sightline/csp/input_error.h"
#include "sightline/domains/camera/level/q3_patch.h"

namespace sightline::camera::q3 {

namespace {

constexpr std::int32_t kVersion = 46;
constexpr int kLumpCount = 17;
constexpr std::size_t kHeaderSize = 4 + 4 + kLumpCount * 8;

// The lumps in header order, with the size of their records (1 for the text and blob lumps).
// clang-format off
enum Lump {
  kEntities = 0, kShaders, kPlanes, kNodes, kLeaves, kLeafFaces, kLeafBrushes, kModels,
  kBrushes, kBrushSides, kVertexes, kMeshVerts, kEffects, kFaces, kLightmaps, kLightVols,
  kVisData,
};
// clang-format on
constexpr const char* kLumpNames[kLumpCount] = {
    "entities",    "shaders", "planes",    "nodes",      "leaves",   "leaffaces",
    "leafbrushes", "models",  "brushes",   "brushsides", "vertexes", "meshverts",
    "effects",     "faces",   "lightmaps", "lightvols",  "visdata"};
// Lightmaps are 128 x 128 RGB, light volumes 8 bytes; visdata is a blob with its own header.
constexpr std::size_t kRecordSizes[kLumpCount] = {
    1, 72, 16, 36, 48, 4, 4, 40, 12, 8, 44, 4, 72, 104, 128 * 128 * 3, 8, 1};

std::uint32_t u32_at(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
std::int32_t i32_at(const unsigned char* p) { return std::bit_cast<std::int32_t>(u32_at(p)); }
float f32_at(const unsigned char* p) { return std::bit_cast<float>(u32_at(p)); }

// One lump: `count` records of `record` bytes at `data`, all inside the file (checked).
struct LumpView {
  const unsigned char* data = nullptr;
  std::size_t count = 0;
  std::size_t record = 1;
  const unsigned char* at(std::size_t i) const { return data + i * record; }
  std::int32_t i32(std::size_t i, std::size_t offset) const { return i32_at(at(i) + offset); }
  float f32(std::size_t i, std::size_t offset) const { return f32_at(at(i) + offset); }
};

class Parser {
 public:
  Parser(std::span<const unsigned char> bytes, const std::string& source)
      : bytes_(bytes), source_(source) {}

  Bsp parse() {
    read_header();
    Bsp bsp;
    read_entities(bsp);
    read_shaders(bsp.tree);
    read_planes(bsp.tree);
    read_brushes(bsp.tree);
    read_leaves(bsp.tree);
    read_nodes(bsp.tree);
    read_models(bsp.tree);
    read_vertices();
    read_faces(bsp);
    return bsp;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw csp::InputError(csp::SourceLocation{source_, 0, 0}, message);
  }
  // "face 12", "node 3" ... for messages, spelled out only when one is thrown (the checks
  // run for every record).
  struct Who {
    const char* what;
    std::size_t index;
    std::string str() const { return std::string(what) + " " + std::to_string(index); }
  };
  void check_index(std::int64_t index, std::size_t size, Who who, const char* field,
                   const char* lump) const {
    if (index < 0 || static_cast<std::uint64_t>(index) >= size) {
      fail(who.str() + ": " + field + " " + std::to_string(index) + " out of range (the map has " +
           std::to_string(size) + " " + lump + ")");
    }
  }
  // first .. first + count (count >= 0) inside [0, size).
  void check_range(std::int64_t first, std::int64_t count, std::size_t size, Who who,
                   const char* what) const {
    if (first < 0 || count < 0 || static_cast<std::uint64_t>(first + count) > size) {
      fail(who.str() + ": " + what + " " + std::to_string(first) + " .. " +
           std::to_string(first + count) + " out of range (the map has " + std::to_string(size) +
           ")");
    }
  }
  void check_finite(float value, Who who, const char* what) const {
    if (!std::isfinite(value)) fail(who.str() + ": " + what + " is not a finite number");
  }

  void read_header() {
    if (bytes_.size() < kHeaderSize) {
      fail("truncated: " + std::to_string(bytes_.size()) + " bytes, shorter than the " +
           std::to_string(kHeaderSize) + "-byte IBSP header");
    }
    if (std::memcmp(bytes_.data(), "IBSP", 4) != 0) {
      fail("not a Quake III map: the file does not start with \"IBSP\"");
    }
    const std::int32_t version = i32_at(bytes_.data() + 4);
    if (version != kVersion) {
      fail("IBSP version " + std::to_string(version) + ", expected 46 (Quake III arena)");
    }
    for (int l = 0; l < kLumpCount; ++l) {
      const unsigned char* entry = bytes_.data() + 8 + 8 * l;
      const std::int64_t offset = i32_at(entry);
      const std::int64_t length = i32_at(entry + 4);
      const std::string who = std::string("lump ") + kLumpNames[l];
      if (offset < 0 || length < 0 || static_cast<std::uint64_t>(offset + length) > bytes_.size()) {
        fail(who + " (offset " + std::to_string(offset) + ", length " + std::to_string(length) +
             ") is not inside the file (" + std::to_string(bytes_.size()) +
             " bytes): truncated or corrupt");
      }
      if (length % static_cast<std::int64_t>(kRecordSizes[l]) != 0) {
        fail(who + ": length " + std::to_string(length) + " is not a multiple of its " +
             std::to_string(kRecordSizes[l]) + "-byte records");
      }
      lumps_[l] = LumpView{bytes_.data() + offset,
                           static_cast<std::size_t>(length) / kRecordSizes[l], kRecordSizes[l]};
    }
  }

  void read_entities(Bsp& bsp) const {
    const LumpView& lump = lumps_[kEntities];
    const auto* begin = reinterpret_cast<const char*>(lump.data);
    // The text ends at its NUL terminator, or at the end of the lump.
    const void* nul = lump.count == 0 ? nullptr : std::memchr(begin, 0, lump.count);
    const std::size_t size = nul == nullptr
                                 ? lump.count
                                 : static_cast<std::size_t>(static_cast<const char*>(nul) - begin);
    bsp.entities.assign(begin, size);
  }

  void read_shaders(BspTree& tree) const {
    const LumpView& lump = lumps_[kShaders];
    tree.shaders.resize(lump.count);
    for (std::size_t i = 0; i < lump.count; ++i) {
      const auto* name = reinterpret_cast<const char*>(lump.at(i));
      const void* nul = std::memchr(name, 0, 64);
      tree.shaders[i].name.assign(
          name,
          nul == nullptr ? 64 : static_cast<std::size_t>(static_cast<const char*>(nul) - name));
      tree.shaders[i].surface_flags = lump.i32(i, 64);
      tree.shaders[i].content_flags = lump.i32(i, 68);
    }
  }

  void read_planes(BspTree& tree) const {
    const LumpView& lump = lumps_[kPlanes];
    tree.planes.resize(lump.count);
    for (std::size_t i = 0; i < lump.count; ++i) {
      Plane& plane = tree.planes[i];
      for (int k = 0; k < 3; ++k) {
        plane.normal[k] = lump.f32(i, 4 * k);
        check_finite(plane.normal[k], Who{"plane", i}, "the normal");
      }
      plane.dist = lump.f32(i, 12);
      check_finite(plane.dist, Who{"plane", i}, "the distance");
    }
  }

  void read_brushes(BspTree& tree) const {
    const LumpView& sides = lumps_[kBrushSides];
    tree.brushsides.resize(sides.count);
    for (std::size_t i = 0; i < sides.count; ++i) {
      BrushSide& side = tree.brushsides[i];
      side.plane = sides.i32(i, 0);
      side.shader = sides.i32(i, 4);
      check_index(side.plane, tree.planes.size(), Who{"brushside", i}, "plane", "planes");
      check_index(side.shader, tree.shaders.size(), Who{"brushside", i}, "shader", "shaders");
    }
    const LumpView& brushes = lumps_[kBrushes];
    tree.brushes.resize(brushes.count);
    for (std::size_t i = 0; i < brushes.count; ++i) {
      Brush& brush = tree.brushes[i];
      brush.first_side = brushes.i32(i, 0);
      brush.side_count = brushes.i32(i, 4);
      brush.shader = brushes.i32(i, 8);
      check_range(brush.first_side, brush.side_count, tree.brushsides.size(), Who{"brush", i},
                  "brushsides");
      check_index(brush.shader, tree.shaders.size(), Who{"brush", i}, "shader", "shaders");
    }
    const LumpView& leafbrushes = lumps_[kLeafBrushes];
    tree.leafbrushes.resize(leafbrushes.count);
    for (std::size_t i = 0; i < leafbrushes.count; ++i) {
      tree.leafbrushes[i] = leafbrushes.i32(i, 0);
      check_index(tree.leafbrushes[i], tree.brushes.size(), Who{"leafbrush", i}, "brush",
                  "brushes");
    }
  }

  void read_leaves(BspTree& tree) const {
    const LumpView& lump = lumps_[kLeaves];
    if (lump.count == 0) fail("the map has no BSP leaves");
    tree.leaves.resize(lump.count);
    for (std::size_t i = 0; i < lump.count; ++i) {
      Leaf& leaf = tree.leaves[i];
      leaf.cluster = lump.i32(i, 0);
      leaf.first_leafbrush = lump.i32(i, 40);
      leaf.leafbrush_count = lump.i32(i, 44);
      check_range(leaf.first_leafbrush, leaf.leafbrush_count, tree.leafbrushes.size(),
                  Who{"leaf", i}, "leafbrushes");
    }
  }

  void read_nodes(BspTree& tree) const {
    const LumpView& lump = lumps_[kNodes];
    if (lump.count == 0) fail("the map has no BSP nodes");
    tree.nodes.resize(lump.count);
    for (std::size_t i = 0; i < lump.count; ++i) {
      Node& node = tree.nodes[i];
      node.plane = lump.i32(i, 0);
      check_index(node.plane, tree.planes.size(), Who{"node", i}, "plane", "planes");
      for (int c = 0; c < 2; ++c) {
        const std::int64_t child = lump.i32(i, 4 + 4 * c);
        node.children[c] = static_cast<std::int32_t>(child);
        if (child < 0) {
          check_index(-(child + 1), tree.leaves.size(), Who{"node", i}, "leaf", "leaves");
        } else if (child <= static_cast<std::int64_t>(i) ||
                   static_cast<std::uint64_t>(child) >= lump.count) {
          // Depth-first storage puts children after their parent; anything else could loop.
          fail(Who{"node", i}.str() + ": child node " + std::to_string(child) +
               " is not after it in the tree (the map has " + std::to_string(lump.count) +
               " nodes)");
        }
      }
    }
  }

  void read_models(BspTree& tree) const {
    const LumpView& lump = lumps_[kModels];
    tree.models.resize(lump.count);
    for (std::size_t i = 0; i < lump.count; ++i) {
      Model& model = tree.models[i];
      for (int k = 0; k < 3; ++k) {
        model.mins[k] = lump.f32(i, 4 * k);
        model.maxs[k] = lump.f32(i, 12 + 4 * k);
        check_finite(model.mins[k], Who{"model", i}, "the bounds");
        check_finite(model.maxs[k], Who{"model", i}, "the bounds");
      }
      model.first_face = lump.i32(i, 24);
      model.face_count = lump.i32(i, 28);
      model.first_brush = lump.i32(i, 32);
      model.brush_count = lump.i32(i, 36);
      check_range(model.first_face, model.face_count, lumps_[kFaces].count, Who{"model", i},
                  "faces");
      check_range(model.first_brush, model.brush_count, tree.brushes.size(), Who{"model", i},
                  "brushes");
    }
  }

  void read_vertices() {
    const LumpView& lump = lumps_[kVertexes];
    positions_.resize(lump.count);
    for (std::size_t i = 0; i < lump.count; ++i) {
      for (int k = 0; k < 3; ++k) {
        positions_[i][k] = lump.f32(i, 4 * k);
        check_finite(positions_[i][k], Who{"vertex", i}, "the position");
      }
    }
  }

  // Why a face is skipped, or nullptr when it becomes triangles.
  static int* skip_counter(const Shader& shader, FaceCounts& counts) {
    if (!shader.solid()) return &counts.not_solid;
    if (!shader.drawn_solid()) return &counts.sky_or_nodraw;
    return nullptr;
  }

  void reserve_triangles(const Bsp& bsp, std::int64_t more, Who who) const {
    if (bsp.triangles.size() + static_cast<std::uint64_t>(more) > kMaxTriangles) {
      fail(who.str() + ": the map would have more than " + std::to_string(kMaxTriangles) +
           " triangles: corrupt (faces sharing a huge vertex range?)");
    }
  }

  std::uint32_t output_vertex(Bsp& bsp, std::size_t vertex) {
    std::uint32_t& slot = remap_[vertex];
    if (slot == kUnused) {
      slot = static_cast<std::uint32_t>(bsp.vertices.size());
      bsp.vertices.push_back(positions_[vertex]);
    }
    return slot;
  }

  void read_faces(Bsp& bsp) {
    const LumpView& faces = lumps_[kFaces];
    const LumpView& meshverts = lumps_[kMeshVerts];
    remap_.assign(positions_.size(), kUnused);
    for (std::size_t f = 0; f < faces.count; ++f) {
      const Who who{"face", f};
      const std::int32_t shader = faces.i32(f, 0);
      const std::int32_t type = faces.i32(f, 8);
      const std::int64_t first_vertex = faces.i32(f, 12);
      const std::int64_t vertex_count = faces.i32(f, 16);
      const std::int64_t first_meshvert = faces.i32(f, 20);
      const std::int64_t meshvert_count = faces.i32(f, 24);
      check_index(shader, bsp.tree.shaders.size(), who, "shader", "shaders");
      if (type < 0 || type > static_cast<std::int32_t>(FaceType::kBillboard)) {
        fail(who.str() + ": unknown face type " + std::to_string(type) +
             " (expected 1 polygon, 2 patch, 3 mesh or 4 billboard)");
      }
      const auto face_type = static_cast<FaceType>(type);
      if (face_type == FaceType::kBad || face_type == FaceType::kBillboard) {
        ++bsp.counts.billboards;
        continue;
      }
      // Polygons, meshes and patches are checked whether kept or not: a corrupt face is a
      // corrupt file.
      check_range(first_vertex, vertex_count, positions_.size(), who, "vertices");
      if (face_type == FaceType::kPatch) {
        const std::int64_t width = faces.i32(f, 96);
        const std::int64_t height = faces.i32(f, 100);
        if (const char* problem = patch_size_problem(width, height, vertex_count)) {
          fail(who.str() + ": patch of " + std::to_string(width) + " x " + std::to_string(height) +
               " control points over " + std::to_string(vertex_count) + " vertices: " + problem);
        }
      } else {
        check_range(first_meshvert, meshvert_count, meshverts.count, who, "meshverts");
        if (meshvert_count % 3 != 0) {
          fail(who.str() + ": " + std::to_string(meshvert_count) +
               " meshverts, not a whole number of triangles");
        }
        for (std::int64_t m = first_meshvert; m < first_meshvert + meshvert_count; ++m) {
          const std::int64_t offset = meshverts.i32(static_cast<std::size_t>(m), 0);
          if (offset < 0 || offset >= vertex_count) {
            fail(who.str() + ": meshvert " + std::to_string(m) + " has vertex offset " +
                 std::to_string(offset) + ", out of range (the face has " +
                 std::to_string(vertex_count) + " vertices)");
          }
        }
      }
      if (int* skipped =
              skip_counter(bsp.tree.shaders[static_cast<std::size_t>(shader)], bsp.counts)) {
        ++*skipped;
        continue;
      }
      FaceTriangles kept{static_cast<std::int32_t>(f), face_type,
                         static_cast<std::uint32_t>(bsp.triangles.size()), 0};
      if (face_type == FaceType::kPatch) {
        const int width = faces.i32(f, 96);
        const int height = faces.i32(f, 100);
        reserve_triangles(bsp, patch_triangle_count(width, height), who);
        tessellate_patch(std::span<const Eigen::Vector3f>(positions_)
                             .subspan(static_cast<std::size_t>(first_vertex),
                                      static_cast<std::size_t>(vertex_count)),
                         width, height, bsp.vertices, bsp.triangles);
        ++bsp.counts.patches;
      } else {
        reserve_triangles(bsp, meshvert_count / 3, who);
        for (std::int64_t m = first_meshvert; m < first_meshvert + meshvert_count; m += 3) {
          std::array<std::uint32_t, 3> corner{};
          for (int k = 0; k < 3; ++k) {
            const auto offset = meshverts.i32(static_cast<std::size_t>(m + k), 0);
            corner[k] = output_vertex(bsp, static_cast<std::size_t>(first_vertex + offset));
          }
          // Clockwise in the file: reversed to counter-clockwise from the front.
          bsp.triangles.push_back({corner[0], corner[2], corner[1]});
        }
        ++(face_type == FaceType::kMesh ? bsp.counts.meshes : bsp.counts.polygons);
      }
      kept.triangle_count = static_cast<std::uint32_t>(bsp.triangles.size()) - kept.first_triangle;
      bsp.faces.push_back(kept);
    }
  }

  static constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();

  std::span<const unsigned char> bytes_;
  const std::string& source_;
  LumpView lumps_[kLumpCount];
  std::vector<Eigen::Vector3f> positions_;  // every vertex of the vertexes lump
  std::vector<std::uint32_t> remap_;        // vertexes lump index -> output vertex
};

}  // namespace

Bsp parse_bsp(std::span<const unsigned char> bytes, const std::string& source) {
  return Parser(bytes, source).parse();
}

}  // namespace sightline::camera::q3
