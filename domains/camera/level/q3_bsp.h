// Quake III arena maps (IBSP version 46) parsed from bytes: the drawn solid triangles and the
// BSP tree with its brushes, in file units (z up).
//
// Why a hand-written parser: Debian has no library for the IBSP format (assimp's Q3BSP
// importer reads only the drawn faces, with none of the shader flags or the brushes the
// solid test needs). The format is a header of 17 (offset, length) lumps, each an array of
// fixed-size little-endian records; this file checks everything before using it, because a
// map is untrusted input and this unit is fuzzed alone (fuzz/): every lump inside the file,
// every lump length a multiple of its record, every index in range, every coordinate finite,
// no integer overflow, a bounded output. Anything else throws csp::InputError naming the
// source. It depends only on the standard library, Eigen and csp/input_error.
//
// What becomes triangles: the faces of type polygon (1), mesh (3) and bezier patch (2,
// tessellated by q3_patch.h) whose shader is solid (CONTENTS_SOLID in its contentFlags) and
// is neither sky (SURF_SKY) nor nodraw (SURF_NODRAW). Billboards (4) and bad faces (0) are
// drawn sprites with no matter: skipped. Maps compiled with q3map2 -patchmeta (most of
// OpenArena's) hold each patch twice: drawn as polygons, and as a patch whose shader record
// has SURF_NODRAW (collision only); the nodraw rule keeps the polygons and drops the copy.
// The faces lump also holds the faces of the brush
// models (doors, platforms, moving walls): they are kept, as solid geometry at rest. Zero-area
// triangles (pinched patches) are kept too: they block nothing and cost little.
//
// Winding: Quake III lists a face's triangles clockwise seen from the front; they are
// reversed here so that (v1 - v0) x (v2 - v0) points out of the surface (up on a floor),
// as TriangleMesh expects.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sightline::camera::q3 {

inline constexpr std::int32_t kContentsSolid = 0x1;  // contentFlags: the brush stops things
inline constexpr std::int32_t kSurfSky = 0x4;        // surfaceFlags: the sky portal
inline constexpr std::int32_t kSurfNodraw = 0x80;    // surfaceFlags: never drawn

// Face types (the `type` field of a face record).
enum class FaceType : std::int32_t {
  kBad = 0,
  kPolygon = 1,
  kPatch = 2,
  kMesh = 3,
  kBillboard = 4
};

struct Shader {
  std::string name;  // "textures/base_wall/concrete" ...
  std::int32_t surface_flags = 0;
  std::int32_t content_flags = 0;
  bool solid() const { return (content_flags & kContentsSolid) != 0; }
  // A face of this shader becomes triangles.
  bool drawn_solid() const { return solid() && (surface_flags & (kSurfSky | kSurfNodraw)) == 0; }
};

struct Plane {
  Eigen::Vector3f normal;  // unit length in a well-formed map (not checked: only finite)
  float dist = 0;          // the plane is {p : normal . p = dist}
};

// An inner node of the BSP tree: front child for normal . p - dist >= 0, back otherwise.
// A child >= 0 is a node (always after its parent: the tree is stored depth-first, which
// the parser checks so that a walk down always ends); a child < 0 is the leaf -(child + 1).
struct Node {
  std::int32_t plane = 0;
  std::array<std::int32_t, 2> children{};
};

struct Leaf {
  std::int32_t cluster = 0;  // < 0: outside the world or opaque
  std::int32_t first_leafbrush = 0;
  std::int32_t leafbrush_count = 0;
};

struct Brush {
  std::int32_t first_side = 0;
  std::int32_t side_count = 0;
  std::int32_t shader = 0;  // its contents are the brush's contents
};

struct BrushSide {
  std::int32_t plane = 0;  // normal points out of the brush
  std::int32_t shader = 0;
};

// A model: model 0 is the world (its brushes are in the tree's leaves); the others are the
// brush entities (doors, platforms, triggers), whose brushes no leaf lists.
struct Model {
  Eigen::Vector3f mins, maxs;  // bounds, file units
  std::int32_t first_face = 0, face_count = 0;
  std::int32_t first_brush = 0, brush_count = 0;
};

// What the solid test needs (q3_solid.h); every index in range, checked by parse_bsp.
struct BspTree {
  std::vector<Shader> shaders;
  std::vector<Plane> planes;
  std::vector<Node> nodes;  // never empty; node 0 is the root of the world
  std::vector<Leaf> leaves;
  std::vector<std::int32_t> leafbrushes;  // brush indices
  std::vector<Brush> brushes;
  std::vector<BrushSide> brushsides;
  std::vector<Model> models;  // may be empty (a map always has the world, but it is unused)
};

// Which faces were kept and which were not, for people and for tests.
struct FaceCounts {
  int polygons = 0;       // type 1, kept
  int meshes = 0;         // type 3, kept
  int patches = 0;        // type 2, kept (tessellated)
  int billboards = 0;     // type 4 and 0, skipped
  int not_solid = 0;      // skipped: shader without CONTENTS_SOLID (water, fog, decals ...)
  int sky_or_nodraw = 0;  // skipped: SURF_SKY or SURF_NODRAW
};

// The triangles of one kept face, for tests and diagnostics.
struct FaceTriangles {
  std::int32_t face = 0;  // index in the faces lump
  FaceType type = FaceType::kPolygon;
  std::uint32_t first_triangle = 0;
  std::uint32_t triangle_count = 0;
};

struct Bsp {
  std::string entities;  // the entity lump's text ("{ "classname" "worldspawn" ... }")
  // The drawn solid surfaces, file units; only vertices used by a triangle are kept.
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise from the front
  std::vector<FaceTriangles> faces;                     // in the order of the faces lump
  FaceCounts counts;
  BspTree tree;
};

// Upper bound on the triangles of one map: far above any real map (a few hundred thousand),
// it keeps a corrupt file whose faces all share one huge vertex range from exhausting memory.
inline constexpr std::size_t kMaxTriangles = std::size_t{1} << 23;

// Parses an IBSP version 46 map. `source` names the bytes in messages (a path, or
// "archive.pk3 (maps/x.bsp)"). Throws csp::InputError for every malformed input.
Bsp parse_bsp(std::span<const unsigned char> bytes, const std::string& source);

}  // namespace sightline::camera::q3
