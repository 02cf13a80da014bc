#include "sightline/experiments/sources/navigation_mesh.h"

#include <DetourNavMesh.h>
#include <DetourNavMeshBuilder.h>
#include <DetourNavMeshQuery.h>
#include <Recast.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>

namespace sightline::experiments {
namespace {

// One tile of at most this many cells (2000 x 2000): Recast's memory stays a few hundred
// MB at worst and a build a few seconds. A bigger level gets coarser cells (stats().note).
constexpr double kMaxCells = 4.0e6;
// Regions smaller than this cannot hold a walk worth the name (a 2 x 2 m patch).
constexpr double kMinRegionArea = 4.0;
// Detour's route buffers: a route through more polygons than this is not planned.
constexpr int kMaxRoutePolygons = 8192;
constexpr int kMaxRoutePoints = 8192;
// Polygon flags: the largest region is walked on, the rest never.
constexpr unsigned short kRegionFlag = 1;
constexpr unsigned short kOtherFlag = 2;

double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

template <class T, void (*Free)(T*)>
struct RecastDeleter {
  void operator()(T* p) const { Free(p); }
};
using HeightfieldPtr =
    std::unique_ptr<rcHeightfield, RecastDeleter<rcHeightfield, rcFreeHeightField>>;
using CompactPtr = std::unique_ptr<rcCompactHeightfield,
                                   RecastDeleter<rcCompactHeightfield, rcFreeCompactHeightfield>>;
using ContoursPtr = std::unique_ptr<rcContourSet, RecastDeleter<rcContourSet, rcFreeContourSet>>;
using PolyMeshPtr = std::unique_ptr<rcPolyMesh, RecastDeleter<rcPolyMesh, rcFreePolyMesh>>;
using DetailPtr =
    std::unique_ptr<rcPolyMeshDetail, RecastDeleter<rcPolyMeshDetail, rcFreePolyMeshDetail>>;

std::string metres(double v) {
  std::ostringstream out;
  out.precision(3);
  out << v;
  return out.str();
}

void require(bool ok, const char* step) {
  if (!ok) throw WalkError(std::string("Recast failed to ") + step + " (out of memory?)");
}

}  // namespace

struct NavigationMesh::Impl {
  dtNavMesh* nav = nullptr;
  dtNavMeshQuery* query = nullptr;
  dtQueryFilter filter;
  std::vector<dtPolyRef> region;   // the largest region's polygons
  std::vector<double> cumulative;  // their areas, summed in order (for drawing points)
  ~Impl() {
    dtFreeNavMeshQuery(query);
    dtFreeNavMesh(nav);
  }
};

NavigationMesh::NavigationMesh(const camera::TriangleMesh& mesh, const WalkOptions& options,
                               const std::vector<Eigen::Vector3d>& anchors)
    : impl_(std::make_unique<Impl>()) {
  const auto start = std::chrono::steady_clock::now();
  if (mesh.empty()) throw WalkError("no walkable region: the level has no triangles");
  const camera::Aabb bounds = mesh.bounds();
  const Eigen::Vector3d extent = bounds.size();

  double cs = options.cell_size, ch = options.cell_height;
  std::string note;
  const double cells = std::ceil(extent.x() / cs + 8) * std::ceil(extent.z() / cs + 8);
  if (cells > kMaxCells) {
    cs = std::sqrt((extent.x() + 8 * cs) * (extent.z() + 8 * cs) / kMaxCells) * 1.01;
    note = "cell size raised from " + metres(options.cell_size) + " to " + metres(cs) +
           " m: the level is " + metres(extent.x()) + " x " + metres(extent.z()) +
           " m, more than one Recast tile of " + metres(kMaxCells) + " cells";
  }
  const double rise = extent.y() + options.agent_height + 2 * ch;
  if (rise / ch > RC_SPAN_MAX_HEIGHT - 64) {
    ch = rise / (RC_SPAN_MAX_HEIGHT - 64) * 1.01;
    note += std::string(note.empty() ? "" : "; ") + "cell height raised from " +
            metres(options.cell_height) + " to " + metres(ch) + " m: the level is " +
            metres(extent.y()) + " m high";
  }

  rcConfig cfg;
  std::memset(&cfg, 0, sizeof cfg);
  cfg.cs = static_cast<float>(cs);
  cfg.ch = static_cast<float>(ch);
  cfg.walkableSlopeAngle = static_cast<float>(options.max_slope_degrees);
  cfg.walkableHeight = static_cast<int>(std::ceil(options.agent_height / ch));
  cfg.walkableClimb = static_cast<int>(std::floor(options.agent_step / ch));
  cfg.walkableRadius = static_cast<int>(std::ceil(options.agent_radius / cs));
  cfg.maxEdgeLen = static_cast<int>(12.0 / cs);
  cfg.maxSimplificationError = 1.3f;
  cfg.minRegionArea = 8 * 8;  // cells: drops specks left by erosion
  cfg.mergeRegionArea = 20 * 20;
  cfg.maxVertsPerPoly = 6;
  cfg.detailSampleDist = static_cast<float>(6 * cs);
  cfg.detailSampleMaxError = static_cast<float>(ch);
  // A margin all round: a level flat along an axis (one wall) still has cells, and the
  // floor's border cells are never clipped by the bounds.
  const double margin[3] = {options.agent_radius + 2 * cs, ch, options.agent_radius + 2 * cs};
  for (int i = 0; i < 3; ++i) {
    cfg.bmin[i] = static_cast<float>(bounds.min[i] - margin[i]);
    cfg.bmax[i] = static_cast<float>(bounds.max[i] + margin[i]);
  }
  // Headroom above the highest floor, so its walkable spans exist.
  cfg.bmax[1] += static_cast<float>(options.agent_height);
  rcCalcGridSize(cfg.bmin, cfg.bmax, cfg.cs, &cfg.width, &cfg.height);
  stats_.grid_width = cfg.width;
  stats_.grid_depth = cfg.height;
  stats_.cell_size = cs;
  stats_.cell_height = ch;
  stats_.note = note;

  std::vector<float> verts;
  verts.reserve(mesh.vertices.size() * 3);
  for (const Eigen::Vector3f& v : mesh.vertices) verts.insert(verts.end(), {v.x(), v.y(), v.z()});
  std::vector<int> tris;
  tris.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t i : t) tris.push_back(static_cast<int>(i));
  }
  const int nv = static_cast<int>(mesh.vertices.size());
  const int nt = static_cast<int>(mesh.triangles.size());

  rcContext ctx(false);
  HeightfieldPtr hf(rcAllocHeightfield());
  require(hf && rcCreateHeightfield(&ctx, *hf, cfg.width, cfg.height, cfg.bmin, cfg.bmax, cfg.cs,
                                    cfg.ch),
          "create the height field");
  // Floors face up (the mesh's front side, TriangleMesh): walls, slopes steeper than the
  // person climbs and ceilings only block.
  std::vector<unsigned char> areas(static_cast<std::size_t>(nt), 0);
  rcMarkWalkableTriangles(&ctx, cfg.walkableSlopeAngle, verts.data(), nv, tris.data(), nt,
                          areas.data());
  const auto walkable_triangles = std::count(areas.begin(), areas.end(), RC_WALKABLE_AREA);
  require(rcRasterizeTriangles(&ctx, verts.data(), nv, tris.data(), areas.data(), nt, *hf,
                               cfg.walkableClimb),
          "rasterise the level");
  rcFilterLowHangingWalkableObstacles(&ctx, cfg.walkableClimb, *hf);
  rcFilterLedgeSpans(&ctx, cfg.walkableHeight, cfg.walkableClimb, *hf);
  rcFilterWalkableLowHeightSpans(&ctx, cfg.walkableHeight, *hf);

  CompactPtr chf(rcAllocCompactHeightfield());
  require(chf && rcBuildCompactHeightfield(&ctx, cfg.walkableHeight, cfg.walkableClimb, *hf, *chf),
          "build the compact height field");
  hf.reset();
  require(rcErodeWalkableArea(&ctx, cfg.walkableRadius, *chf), "erode by the person's radius");
  require(rcBuildDistanceField(&ctx, *chf), "build the distance field");
  require(rcBuildRegions(&ctx, *chf, 0, cfg.minRegionArea, cfg.mergeRegionArea),
          "build the regions");
  ContoursPtr cset(rcAllocContourSet());
  require(cset && rcBuildContours(&ctx, *chf, cfg.maxSimplificationError, cfg.maxEdgeLen, *cset),
          "build the contours");
  const auto no_region = [&](const std::string& why) {
    std::ostringstream out;
    out << "no walkable region for a person " << options.agent_height << " m tall, "
        << 2 * options.agent_radius << " m wide, stepping " << options.agent_step
        << " m, on slopes up to " << options.max_slope_degrees << " degrees: " << why
        << " (the level: " << nt << " triangles, " << walkable_triangles
        << " of them floors, within " << metres(extent.x()) << " x " << metres(extent.y()) << " x "
        << metres(extent.z()) << " m)";
    if (walkable_triangles == 0) {
      out << "; a floor is a triangle facing up, counter-clockwise seen from above";
    }
    return WalkError(out.str());
  };
  if (cset->nconts == 0) throw no_region("no floor is large enough with room above it");
  PolyMeshPtr pmesh(rcAllocPolyMesh());
  require(pmesh && rcBuildPolyMesh(&ctx, *cset, cfg.maxVertsPerPoly, *pmesh), "build polygons");
  if (pmesh->npolys == 0) throw no_region("no floor is large enough with room above it");
  DetailPtr dmesh(rcAllocPolyMeshDetail());
  require(dmesh && rcBuildPolyMeshDetail(&ctx, *pmesh, *chf, cfg.detailSampleDist,
                                         cfg.detailSampleMaxError, *dmesh),
          "build the detail mesh");
  for (int i = 0; i < pmesh->npolys; ++i) pmesh->flags[i] = kOtherFlag;

  dtNavMeshCreateParams params;
  std::memset(&params, 0, sizeof params);
  params.verts = pmesh->verts;
  params.vertCount = pmesh->nverts;
  params.polys = pmesh->polys;
  params.polyAreas = pmesh->areas;
  params.polyFlags = pmesh->flags;
  params.polyCount = pmesh->npolys;
  params.nvp = pmesh->nvp;
  params.detailMeshes = dmesh->meshes;
  params.detailVerts = dmesh->verts;
  params.detailVertsCount = dmesh->nverts;
  params.detailTris = dmesh->tris;
  params.detailTriCount = dmesh->ntris;
  params.walkableHeight = static_cast<float>(options.agent_height);
  params.walkableRadius = static_cast<float>(options.agent_radius);
  params.walkableClimb = static_cast<float>(options.agent_step);
  rcVcopy(params.bmin, pmesh->bmin);
  rcVcopy(params.bmax, pmesh->bmax);
  params.cs = cfg.cs;
  params.ch = cfg.ch;
  params.buildBvTree = true;
  unsigned char* data = nullptr;
  int size = 0;
  if (!dtCreateNavMeshData(&params, &data, &size)) {
    throw WalkError("Detour could not make a navigation mesh of " + std::to_string(pmesh->nverts) +
                    " vertices and " + std::to_string(pmesh->npolys) +
                    " polygons (at most 65535 vertices in one tile: raise --cell-size)");
  }
  impl_->nav = dtAllocNavMesh();
  if (!impl_->nav || dtStatusFailed(impl_->nav->init(data, size, DT_TILE_FREE_DATA))) {
    dtFree(data);
    throw WalkError("Detour could not load the navigation mesh");
  }
  impl_->query = dtAllocNavMeshQuery();
  if (!impl_->query || dtStatusFailed(impl_->query->init(impl_->nav, 65535))) {
    throw WalkError("Detour could not make a route planner");
  }

  // Connected regions: flood over the polygons' links, keep the largest by area.
  const dtNavMesh& nav = *impl_->nav;
  const dtMeshTile* tile = nav.getTile(0);
  const int npolys = tile->header->polyCount;
  std::vector<double> area(static_cast<std::size_t>(npolys), 0.0);
  for (int i = 0; i < npolys; ++i) {
    const dtPoly& p = tile->polys[i];
    double twice = 0;  // shoelace on x and z
    for (int j = 0; j < p.vertCount; ++j) {
      const float* a = &tile->verts[p.verts[j] * 3];
      const float* b = &tile->verts[p.verts[(j + 1) % p.vertCount] * 3];
      twice += static_cast<double>(a[0]) * b[2] - static_cast<double>(b[0]) * a[2];
    }
    area[static_cast<std::size_t>(i)] = std::abs(twice) / 2;
    stats_.walkable_area += std::abs(twice) / 2;
  }
  std::vector<int> component(static_cast<std::size_t>(npolys), -1);
  std::vector<double> component_area;
  std::vector<int> stack;
  for (int seed = 0; seed < npolys; ++seed) {
    if (component[static_cast<std::size_t>(seed)] >= 0) continue;
    const int id = static_cast<int>(component_area.size());
    component_area.push_back(0);
    component[static_cast<std::size_t>(seed)] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      component_area.back() += area[static_cast<std::size_t>(i)];
      for (unsigned k = tile->polys[i].firstLink; k != DT_NULL_LINK; k = tile->links[k].next) {
        const auto j = static_cast<int>(nav.decodePolyIdPoly(tile->links[k].ref));
        if (j < npolys && component[static_cast<std::size_t>(j)] < 0) {
          component[static_cast<std::size_t>(j)] = id;
          stack.push_back(j);
        }
      }
    }
  }
  // The region walked: most anchors on it, then the largest.
  std::vector<int> anchored(component_area.size(), 0);
  dtQueryFilter any;
  any.setIncludeFlags(0xffff);
  const float reach[3] = {1.0f, 2.5f, 1.0f};  // a spawn point is a player's centre, ~0.75 m up
  for (const Eigen::Vector3d& a : anchors) {
    const float p[3] = {static_cast<float>(a.x()), static_cast<float>(a.y()),
                        static_cast<float>(a.z())};
    dtPolyRef ref = 0;
    float nearest[3];
    if (dtStatusSucceed(impl_->query->findNearestPoly(p, reach, &any, &ref, nearest)) && ref != 0) {
      ++anchored[static_cast<std::size_t>(component[nav.decodePolyIdPoly(ref)])];
    }
  }
  int largest = 0;
  for (int c = 1; c < static_cast<int>(component_area.size()); ++c) {
    const auto k = static_cast<std::size_t>(c), best = static_cast<std::size_t>(largest);
    if (anchored[k] > anchored[best] ||
        (anchored[k] == anchored[best] && component_area[k] > component_area[best])) {
      largest = c;
    }
  }
  stats_.anchors = static_cast<int>(anchors.size());
  stats_.region_anchors = anchored[static_cast<std::size_t>(largest)];
  const dtPolyRef base = nav.getPolyRefBase(tile);
  double total = 0;
  for (int i = 0; i < npolys; ++i) {
    if (component[static_cast<std::size_t>(i)] != largest) continue;
    impl_->nav->setPolyFlags(base | static_cast<dtPolyRef>(i), kRegionFlag);
    impl_->region.push_back(base | static_cast<dtPolyRef>(i));
    total += area[static_cast<std::size_t>(i)];
    impl_->cumulative.push_back(total);
  }
  impl_->filter.setIncludeFlags(kRegionFlag);
  impl_->filter.setExcludeFlags(0);
  stats_.polygons = npolys;
  stats_.region_polygons = static_cast<int>(impl_->region.size());
  stats_.region_area = total;
  stats_.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (total < kMinRegionArea) {
    throw no_region("the connected floor walked is only " + metres(total) + " m^2, a walk needs " +
                    metres(kMinRegionArea));
  }
}

NavigationMesh::~NavigationMesh() = default;

Eigen::Vector3d NavigationMesh::random_point(std::mt19937_64& rng) const {
  const auto& cum = impl_->cumulative;
  const double pick = unit(rng) * cum.back();
  const auto k = static_cast<std::size_t>(
      std::min<std::ptrdiff_t>(std::upper_bound(cum.begin(), cum.end(), pick) - cum.begin(),
                               static_cast<std::ptrdiff_t>(cum.size()) - 1));
  const dtPolyRef ref = impl_->region[k];
  const dtMeshTile* tile = nullptr;
  const dtPoly* poly = nullptr;
  impl_->nav->getTileAndPolyByRefUnsafe(ref, &tile, &poly);
  const auto vertex = [&](int j) {
    const float* v = &tile->verts[poly->verts[j] * 3];
    return Eigen::Vector3d(v[0], v[1], v[2]);
  };
  // The polygon is convex: a fan of triangles from its first vertex, one drawn by area.
  std::vector<double> fan;
  double sum = 0;
  for (int j = 1; j + 1 < poly->vertCount; ++j) {
    sum += ((vertex(j) - vertex(0)).cross(vertex(j + 1) - vertex(0))).y() * 0.5;
    fan.push_back(std::abs(sum));
  }
  const double pick_triangle = unit(rng) * fan.back();
  int j = 1;
  while (j + 2 < poly->vertCount && fan[static_cast<std::size_t>(j - 1)] < pick_triangle) ++j;
  double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
  Eigen::Vector3d p = (1 - r1) * vertex(0) + r1 * (1 - r2) * vertex(j) + r1 * r2 * vertex(j + 1);
  float pos[3] = {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
  float height = pos[1];
  if (dtStatusSucceed(impl_->query->getPolyHeight(ref, pos, &height))) p.y() = height;
  return p;
}

std::vector<NavigationMesh::RoutePoint> NavigationMesh::route(const Eigen::Vector3d& from,
                                                              const Eigen::Vector3d& to) const {
  const float half[3] = {0.5f, 2.0f, 0.5f};
  float a[3] = {static_cast<float>(from.x()), static_cast<float>(from.y()),
                static_cast<float>(from.z())};
  float b[3] = {static_cast<float>(to.x()), static_cast<float>(to.y()), static_cast<float>(to.z())};
  dtPolyRef start = 0, end = 0;
  float sa[3], sb[3];
  const dtNavMeshQuery& q = *impl_->query;
  if (dtStatusFailed(q.findNearestPoly(a, half, &impl_->filter, &start, sa)) || start == 0)
    return {};
  if (dtStatusFailed(q.findNearestPoly(b, half, &impl_->filter, &end, sb)) || end == 0) return {};
  std::vector<dtPolyRef> polys(kMaxRoutePolygons);
  int npolys = 0;
  const dtStatus found =
      q.findPath(start, end, sa, sb, &impl_->filter, polys.data(), &npolys, kMaxRoutePolygons);
  if (dtStatusFailed(found) || (found & DT_PARTIAL_RESULT) || npolys == 0 ||
      polys[static_cast<std::size_t>(npolys - 1)] != end) {
    return {};
  }
  // Twice: the corners alone, then with every polygon crossing (for the heights).
  std::vector<float> points(kMaxRoutePoints * 3);
  std::vector<unsigned char> flags(kMaxRoutePoints);
  std::vector<dtPolyRef> refs(kMaxRoutePoints);
  const auto straight_path = [&](int options) {
    int n = 0;
    const dtStatus s = q.findStraightPath(sa, sb, polys.data(), npolys, points.data(), flags.data(),
                                          refs.data(), &n, kMaxRoutePoints, options);
    std::vector<Eigen::Vector3d> out;
    if (dtStatusFailed(s) || (s & DT_BUFFER_TOO_SMALL)) return out;
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
      if (out.empty() || (p - out.back()).norm() > 1e-4) out.push_back(p);
    }
    return out;
  };
  const std::vector<Eigen::Vector3d> corners = straight_path(0);
  const std::vector<Eigen::Vector3d> all = straight_path(DT_STRAIGHTPATH_ALL_CROSSINGS);
  if (corners.size() < 2 || all.size() < 2) return {};
  std::vector<RoutePoint> out;
  std::size_t next_corner = 0;
  for (const Eigen::Vector3d& p : all) {
    const bool corner = next_corner < corners.size() && (p - corners[next_corner]).norm() < 1e-3;
    if (corner) ++next_corner;
    out.push_back({p, corner});
  }
  // Every corner must have been met, in order; else the two answers disagree.
  if (next_corner != corners.size() || !out.front().corner || !out.back().corner) return {};
  return out;
}

double route_length(const std::vector<NavigationMesh::RoutePoint>& route) {
  double length = 0;
  for (std::size_t i = 1; i < route.size(); ++i) {
    length += (route[i].position - route[i - 1].position).norm();
  }
  return length;
}

}  // namespace sightline::experiments
