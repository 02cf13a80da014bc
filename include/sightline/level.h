/* sightline/level.h: loading a game level's triangles (the `levels` component, C API).
 *
 * Quake III maps (.bsp, or a .pk3 naming the map) and mesh files through assimp, as
 * FORMATS.md's scene `level:` block reads them: metres, y up. A game has its own level data
 * and never needs this; it is for tools, examples and research code that take sightline's
 * levels. Not part of the runtime camera library (it links the file importers).
 *
 * Errors: a NULL return, with sl_level_last_error() saying the file and what was wrong.
 */
#ifndef SIGHTLINE_LEVEL_H
#define SIGHTLINE_LEVEL_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sl_level sl_level;

/* `map` names the map inside a .pk3 holding several (NULL otherwise). The format's defaults
 * apply (Quake III: 1/32 m per unit, z up, turned to y up). */
sl_level* sl_level_load(const char* file, const char* map);
/* The level's triangles: *vertices holds 3 doubles per vertex, *indices 3 per triangle. The
 * arrays belong to the level. */
void sl_level_triangles(const sl_level* level, const double** vertices, size_t* vertex_count,
                        const uint32_t** indices, size_t* triangle_count);
void sl_level_destroy(sl_level* level);
const char* sl_level_last_error(void);

#ifdef __cplusplus
}
#endif

#endif /* SIGHTLINE_LEVEL_H */
