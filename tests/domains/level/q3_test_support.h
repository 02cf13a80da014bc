// Test support for the Quake III reader: the OpenArena maps Debian installs, extracted with
// tools other than the reader's own (unzip, else python3's zipfile), and a minimal
// independent reading of the IBSP lumps, written from the format description, so that the
// tests compare the reader with something that does not share its code.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace sightline::camera::q3test {

inline const std::string kPak088 = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3";

// Skips the test when the OpenArena data is not installed.
#define SKIP_WITHOUT_OPENARENA()                                        \
  do {                                                                  \
    if (!std::filesystem::exists(::sightline::camera::q3test::kPak088)) \
      GTEST_SKIP() << "no " << ::sightline::camera::q3test::kPak088     \
                   << " (Debian's openarena-088-data)";                 \
  } while (0)

inline bool have_program(const char* name) {
  return std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0;
}

inline std::vector<unsigned char> read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& path, const std::vector<unsigned char>& b) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

inline std::filesystem::path scratch_dir() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("sightline_q3_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

// maps/<map>.bsp of the 0.8.8 pak, extracted by `unzip` or python3 (not by the reader's
// libzip code). Empty path (and `why` set) when neither tool is there.
inline std::filesystem::path extract_map(const std::string& map, std::string* why) {
  const auto out = scratch_dir() / (map + ".bsp");
  if (std::filesystem::exists(out)) return out;
  const std::string entry = "maps/" + map + ".bsp";
  std::string command;
  if (have_program("unzip")) {
    command = "unzip -p '" + kPak088 + "' '" + entry + "' > '" + out.string() + "'";
  } else if (have_program("python3")) {
    command = "python3 -c \"import sys,zipfile; sys.stdout.buffer.write(zipfile.ZipFile('" +
              kPak088 + "').read('" + entry + "'))\" > '" + out.string() + "'";
  } else {
    *why = "neither unzip nor python3 is installed to extract " + entry;
    return {};
  }
  if (std::system(command.c_str()) != 0 || std::filesystem::file_size(out) == 0) {
    *why = "extraction failed: " + command;
    std::filesystem::remove(out);
    return {};
  }
  return out;
}

// --- A minimal IBSP reading, from the format description (little-endian records). ---
inline std::int32_t le_i32(const std::vector<unsigned char>& b, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | b.at(at + static_cast<std::size_t>(k));
  return static_cast<std::int32_t>(v);
}
inline float le_f32(const std::vector<unsigned char>& b, std::size_t at) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(le_i32(b, at)));
}
inline void put_i32(std::vector<unsigned char>& b, std::size_t at, std::int32_t value) {
  const auto v = static_cast<std::uint32_t>(value);
  for (int k = 0; k < 4; ++k) b.at(at + static_cast<std::size_t>(k)) = (v >> (8 * k)) & 0xff;
}
// Header entry of lump `l`: its offset field is at 8 + 8 l, its length at 12 + 8 l.
inline std::size_t lump_offset(const std::vector<unsigned char>& b, int l) {
  return static_cast<std::size_t>(le_i32(b, 8 + 8 * static_cast<std::size_t>(l)));
}
inline std::size_t lump_length(const std::vector<unsigned char>& b, int l) {
  return static_cast<std::size_t>(le_i32(b, 12 + 8 * static_cast<std::size_t>(l)));
}
inline Eigen::Vector3d vec_at(const std::vector<unsigned char>& b, std::size_t at) {
  return {le_f32(b, at), le_f32(b, at + 4), le_f32(b, at + 8)};
}

// Lump numbers and record sizes used below (Quake III's BSP format description).
enum : int {
  kShadersLump = 1,
  kPlanesLump = 2,
  kNodesLump = 3,
  kLeavesLump = 4,
  kLeafBrushesLump = 6,
  kBrushesLump = 8,
  kBrushSidesLump = 9,
  kVertexesLump = 10,
  kMeshVertsLump = 11,
  kFacesLump = 13
};
constexpr std::size_t kShaderBytes = 72, kVertexBytes = 44, kFaceBytes = 104;

// The entity lump's text, the entities as key -> value maps (no escapes in Quake III).
inline std::vector<std::map<std::string, std::string>> entities(
    const std::vector<unsigned char>& b) {
  const std::string text(reinterpret_cast<const char*>(b.data()) + lump_offset(b, 0),
                         lump_length(b, 0));
  std::vector<std::map<std::string, std::string>> out;
  std::map<std::string, std::string> current;
  std::vector<std::string> strings;
  for (std::size_t i = 0; i < text.size() && text[i] != 0; ++i) {
    if (text[i] == '{') {
      current.clear();
      strings.clear();
    } else if (text[i] == '}') {
      for (std::size_t k = 0; k + 1 < strings.size(); k += 2) current[strings[k]] = strings[k + 1];
      out.push_back(current);
    } else if (text[i] == '"') {
      const std::size_t end = text.find('"', i + 1);
      strings.push_back(text.substr(i + 1, end - i - 1));
      i = end;
    }
  }
  return out;
}

// Player spawn origins (info_player_deathmatch and info_player_start), file units.
inline std::vector<Eigen::Vector3d> spawn_points(const std::vector<unsigned char>& b) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& e : entities(b)) {
    const auto cls = e.find("classname");
    const auto origin = e.find("origin");
    if (cls == e.end() || origin == e.end()) continue;
    if (cls->second != "info_player_deathmatch" && cls->second != "info_player_start") continue;
    Eigen::Vector3d p;
    std::sscanf(origin->second.c_str(), "%lf %lf %lf", &p.x(), &p.y(), &p.z());
    out.push_back(p);
  }
  return out;
}

// Counted straight from the lumps: what the reader should produce.
struct IndependentCount {
  std::size_t triangles = 0;        // meshverts / 3 of kept polygons and meshes, plus patches
  std::size_t patch_triangles = 0;  // 2 * 8 * 8 per 3 x 3 sub-patch (q3_patch.h's level 8)
  std::size_t kept_faces = 0;
  // Bounds that the reader's must lie between: `inner` holds the points surely on the
  // surface (mesh vertices, patch corner control points), `outer` also the patch control
  // points off the surface (a bezier patch lies in their convex hull).
  Eigen::Vector3d inner_min = Eigen::Vector3d::Constant(1e30), inner_max = -inner_min;
  Eigen::Vector3d outer_min = inner_min, outer_max = inner_max;
};

inline IndependentCount count_independently(const std::vector<unsigned char>& b) {
  IndependentCount c;
  const std::size_t shaders = lump_offset(b, kShadersLump);
  const std::size_t vertexes = lump_offset(b, kVertexesLump);
  const std::size_t faces = lump_offset(b, kFacesLump);
  const std::size_t face_count = lump_length(b, kFacesLump) / kFaceBytes;
  auto vertex = [&](std::size_t v) { return vec_at(b, vertexes + v * kVertexBytes); };
  for (std::size_t f = 0; f < face_count; ++f) {
    const std::size_t at = faces + f * kFaceBytes;
    const auto shader = static_cast<std::size_t>(le_i32(b, at));
    const std::int32_t type = le_i32(b, at + 8);
    const std::int32_t surface = le_i32(b, shaders + shader * kShaderBytes + 64);
    const std::int32_t contents = le_i32(b, shaders + shader * kShaderBytes + 68);
    if ((contents & 1) == 0 || (surface & 0x4) != 0 || (surface & 0x80) != 0) continue;
    const auto first = static_cast<std::size_t>(le_i32(b, at + 12));
    if (type == 1 || type == 3) {
      ++c.kept_faces;
      const auto meshvert = static_cast<std::size_t>(le_i32(b, at + 20));
      const auto n = static_cast<std::size_t>(le_i32(b, at + 24));
      c.triangles += n / 3;
      for (std::size_t m = 0; m < n; ++m) {
        const auto offset = static_cast<std::size_t>(
            le_i32(b, lump_offset(b, kMeshVertsLump) + 4 * (meshvert + m)));
        const Eigen::Vector3d p = vertex(first + offset);
        c.inner_min = c.inner_min.cwiseMin(p), c.inner_max = c.inner_max.cwiseMax(p);
      }
    } else if (type == 2) {
      ++c.kept_faces;
      const auto w = static_cast<std::size_t>(le_i32(b, at + 96));
      const auto h = static_cast<std::size_t>(le_i32(b, at + 100));
      const std::size_t t = (w - 1) / 2 * ((h - 1) / 2) * 2 * 8 * 8;
      c.triangles += t;
      c.patch_triangles += t;
      for (std::size_t row = 0; row < h; ++row) {
        for (std::size_t col = 0; col < w; ++col) {
          const Eigen::Vector3d p = vertex(first + row * w + col);
          c.outer_min = c.outer_min.cwiseMin(p), c.outer_max = c.outer_max.cwiseMax(p);
          if (row % 2 == 0 && col % 2 == 0) {
            c.inner_min = c.inner_min.cwiseMin(p), c.inner_max = c.inner_max.cwiseMax(p);
          }
        }
      }
    }
  }
  c.outer_min = c.outer_min.cwiseMin(c.inner_min);
  c.outer_max = c.outer_max.cwiseMax(c.inner_max);
  return c;
}

}  // namespace sightline::camera::q3test
