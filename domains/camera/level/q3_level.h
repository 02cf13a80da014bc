// Quake III arena maps as levels: the `.bsp` / `.pk3` branch of load_level (level.h).
//
// Reads the map's bytes (from the .bsp, or from maps/<map>.bsp inside the .pk3 through
// pk3_archive.h), parses them (q3_bsp.h), keeps the triangles of the solid surfaces that are
// neither sky nor nodraw (patches tessellated), maps them to the scene's frame with
// `transform`, and attaches the brushes as the level's SolidVolume (q3_solid.h).
#pragma once

#include "sightline/domains/camera/level/level.h"

namespace sightline::camera {

// Throws csp::InputError naming the file (and the map) for every bad input: a missing file,
// an unknown map (the message lists the maps the .pk3 holds), a truncated or corrupt BSP.
Level load_quake3_level(const LevelSpec& spec, const LevelTransform& transform);

}  // namespace sightline::camera
