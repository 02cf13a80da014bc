// Spawn points: where a Quake III map puts its players, read from the map's entities.
//
// They are where people are known to stand. A game map may hold a walkable floor bigger
// than its arena that nobody plays on (a floor far below the map, under its sky: 2 of the
// 50 OpenArena maps, oa_koth2 and czest2ctf); the walks keep to the region holding the
// spawn points (generate_walks' anchors).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sightline/domains/camera/level/level.h"

namespace sightline::experiments {

// The origins of the map's info_player_* entities and team spawns (team_CTF_*player,
// team_CTF_*spawn), mapped into the scene's frame by `transform` (the loaded level's).
// Empty for levels that are not Quake III maps. Throws csp::InputError as load_level does.
std::vector<Eigen::Vector3d> quake3_spawn_points(const camera::LevelSpec& spec,
                                                 const camera::LevelTransform& transform);

}  // namespace sightline::experiments
