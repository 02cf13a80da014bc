// Pk3Archive: the maps inside a Quake III .pk3 (a zip archive), read through libzip.
//
// A .pk3 holds a game's data; its maps are the entries maps/<name>.bsp. FORMATS.md lets a
// scene name one with `map` as "oa_thor", "oa_thor.bsp" or "maps/oa_thor.bsp" (letter case
// ignored, as Quake III's own file system does), and requires it when the archive holds
// several. Everything that goes wrong (a missing file, not a zip, an unknown map, a corrupt
// or oversized entry) is a csp::InputError naming the archive; an unknown map's message lists
// the maps the archive holds.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

struct zip;  // libzip's archive handle (zip_t), kept out of this header

namespace sightline::camera {

class Pk3Archive {
 public:
  // Opens the archive (read only). Throws csp::InputError naming `path`.
  explicit Pk3Archive(std::string path);
  ~Pk3Archive();
  Pk3Archive(const Pk3Archive&) = delete;
  Pk3Archive& operator=(const Pk3Archive&) = delete;

  const std::string& path() const { return path_; }
  // The archive's map entries ("maps/aggressor.bsp" ...: .bsp files directly under maps/),
  // sorted.
  std::vector<std::string> map_entries() const;
  // The entry `map` selects: "oa_thor", "oa_thor.bsp" or "maps/oa_thor.bsp", any case; empty
  // selects the only map. Throws csp::InputError for no map, several maps and no `map`, or
  // an unknown map (listing the archive's maps).
  std::string select_map(const std::string& map) const;
  // One entry's bytes. Throws csp::InputError for a missing, corrupt (CRC, inflate) or
  // oversized entry (above kMaxEntryBytes).
  std::vector<unsigned char> read(const std::string& entry) const;

  // Far above any real map (oa_thor.bsp is 8 MB): a corrupt size field allocates no more.
  static constexpr std::size_t kMaxEntryBytes = std::size_t{1} << 30;

 private:
  std::string path_;
  zip* archive_ = nullptr;
};

}  // namespace sightline::camera
