// The C API (sightline/sightline.h): every kind of bad input gets a status and a message,
// never a crash; a camera made through it films a world of callbacks.
#include "sightline/sightline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "box_oracle.h"

namespace {

// A callback world over one pillar, by the test's oracle; `fail_after` calls it reports
// error 7 (a physics query that failed), -1 never.
struct PillarWorld {
  std::vector<sightline::Box> boxes{sightline::Box{{0.7, 0, 2}, {1.7, 3, 3}}};  // beside the walk
  long calls = 0;
  long fail_after = -1;
  bool failing() { return fail_after >= 0 && calls++ >= fail_after; }
};

int first_hit(void* user, const sl_vec3* a, const sl_vec3* b, double, int* hit, double* fraction,
              sl_vec3* normal) {
  auto* w = static_cast<PillarWorld*>(user);
  if (w->failing()) return 7;
  const bool clear = box_oracle::clear(w->boxes, {a->x, a->y, a->z}, {b->x, b->y, b->z});
  *hit = clear ? 0 : 1;
  *fraction = 0.5;  // coarse, as a cheap game query may be
  *normal = sl_vec3{0, 0, -1};
  return 0;
}

int clearance(void* user, const sl_vec3* p, double limit, double, double* distance) {
  auto* w = static_cast<PillarWorld*>(user);
  if (w->failing()) return 7;
  *distance = std::min(limit, box_oracle::distance({p->x, p->y, p->z}, w->boxes[0]));
  return 0;
}

sl_world* callback_world(PillarWorld* w) {
  sl_world_callbacks c{first_hit, clearance, nullptr, w};
  sl_world* world = nullptr;
  EXPECT_EQ(sl_world_create_callbacks(&c, &world), SL_OK) << sl_last_error();
  return world;
}

sl_person_state walker(double t) {
  return sl_person_state{{0, 0, -4 + 1.4 * t}, {0, 0, 1.4}, 0};
}

sl_camera* camera_of(sl_world* world) {
  sl_camera_settings s;
  sl_camera_settings_default(&s);
  const sl_person_state first = walker(0);
  sl_camera* camera = nullptr;
  EXPECT_EQ(sl_camera_create(world, &s, &first, 1, 0.0, &camera), SL_OK) << sl_last_error();
  return camera;
}

TEST(CApi, NullHandlesAreRefused) {
  sl_pose pose{};
  const sl_person_state p = walker(0);
  EXPECT_EQ(sl_camera_update(nullptr, &p, 1, 0.1, &pose), SL_ERROR_INVALID_HANDLE);
  EXPECT_NE(std::string(sl_last_error()).find("not a live camera"), std::string::npos);
  EXPECT_EQ(sl_camera_reset(nullptr, sl_vec3{0, 0, 0}), SL_ERROR_INVALID_HANDLE);
  int clear = 0;
  EXPECT_EQ(sl_world_line_of_sight(nullptr, {0, 0, 0}, {1, 1, 1}, 0, &clear), SL_ERROR_INVALID_HANDLE);
  sl_camera_settings s;
  sl_camera_settings_default(&s);
  sl_camera* camera = nullptr;
  EXPECT_EQ(sl_camera_create(nullptr, &s, &p, 1, 0, &camera), SL_ERROR_INVALID_HANDLE);
  EXPECT_EQ(camera, nullptr);
  sl_world_destroy(nullptr);  // ignored
  sl_camera_destroy(nullptr);
  // A pointer that was never a handle (here: of the wrong kind).
  PillarWorld w;
  sl_world* world = callback_world(&w);
  EXPECT_EQ(sl_camera_update(reinterpret_cast<sl_camera*>(world), &p, 1, 0.1, &pose),
            SL_ERROR_INVALID_HANDLE);
  sl_world_destroy(world);
}

TEST(CApi, MissingCallbacksAreRefused) {
  sl_world_callbacks c{nullptr, clearance, nullptr, nullptr};
  sl_world* world = nullptr;
  EXPECT_EQ(sl_world_create_callbacks(&c, &world), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sl_world_create_callbacks(nullptr, &world), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(world, nullptr);
}

TEST(CApi, DestroyedHandlesAreRefusedAndCamerasKeepTheirWorld) {
  PillarWorld w;
  sl_world* world = callback_world(&w);
  sl_camera* camera = camera_of(world);
  sl_world_destroy(world);  // the camera keeps the world alive
  sl_camera_settings s;
  sl_camera_settings_default(&s);
  const sl_person_state p0 = walker(0);
  sl_camera* another = nullptr;
  EXPECT_EQ(sl_camera_create(world, &s, &p0, 1, 0, &another), SL_ERROR_INVALID_HANDLE);
  EXPECT_NE(std::string(sl_last_error()).find("not a live world"), std::string::npos);
  sl_pose pose{};
  const sl_person_state p1 = walker(1.0 / 60);
  EXPECT_EQ(sl_camera_update(camera, &p1, 1, 1.0 / 60, &pose), SL_OK) << sl_last_error();
  sl_camera_destroy(camera);
  EXPECT_EQ(sl_camera_update(camera, &p1, 1, 1.0 / 60, &pose), SL_ERROR_INVALID_HANDLE);
}

TEST(CApi, NanStatesAndBadArgumentsAreRefusedAndTheCameraGoesOn) {
  PillarWorld w;
  sl_world* world = callback_world(&w);
  sl_camera* camera = camera_of(world);
  sl_pose pose{};
  sl_person_state bad = walker(0.1);
  bad.velocity.y = std::nan("");
  EXPECT_EQ(sl_camera_update(camera, &bad, 1, 1.0 / 60, &pose), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sl_last_error()).find("not finite"), std::string::npos);
  const sl_person_state good = walker(1.0 / 60);
  EXPECT_EQ(sl_camera_update(camera, &good, 1, 0.0, &pose), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sl_camera_update(camera, &good, 1, std::nan(""), &pose), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sl_camera_update(camera, &good, 2, 1.0 / 60, &pose), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sl_camera_update(camera, &good, 1, 1.0 / 60, nullptr), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sl_camera_update(camera, &good, 1, 1.0 / 60, &pose), SL_OK) << sl_last_error();
  EXPECT_TRUE(std::isfinite(pose.position.x));
  EXPECT_EQ(sl_camera_reset(camera, sl_vec3{std::nan(""), 0, 0}), SL_ERROR_INVALID_ARGUMENT);
  sl_camera_destroy(camera);
  sl_world_destroy(world);
}

TEST(CApi, UnknownPresetsAndSolversAreNamed) {
  PillarWorld w;
  sl_world* world = callback_world(&w);
  sl_camera_settings s;
  sl_camera_settings_default(&s);
  const sl_person_state p = walker(0);
  sl_camera* camera = nullptr;
  s.profile = "cinematic";
  EXPECT_EQ(sl_camera_create(world, &s, &p, 1, 0, &camera), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sl_last_error()).find("anticipating"), std::string::npos);  // the list
  s.profile = nullptr;
  s.solver = "simulated-annealing";
  EXPECT_EQ(sl_camera_create(world, &s, &p, 1, 0, &camera), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sl_last_error()).find("occlusion-octree"), std::string::npos);
  s.solver = nullptr;
  s.people_count = 0;
  EXPECT_EQ(sl_camera_create(world, &s, &p, 1, 0, &camera), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(camera, nullptr);
  sl_world_destroy(world);
}

TEST(CApi, ACallbackErrorBecomesAWorldErrorAndTheCameraRecovers) {
  PillarWorld w;
  sl_world* world = callback_world(&w);
  sl_camera* camera = camera_of(world);
  sl_pose pose{};
  sl_person_state p = walker(1.0 / 60);
  ASSERT_EQ(sl_camera_update(camera, &p, 1, 1.0 / 60, &pose), SL_OK) << sl_last_error();
  w.calls = 0;
  w.fail_after = 3;  // fails part-way through the next frame
  p = walker(2.0 / 60);
  EXPECT_EQ(sl_camera_update(camera, &p, 1, 1.0 / 60, &pose), SL_ERROR_WORLD);
  EXPECT_NE(std::string(sl_last_error()).find("error 7"), std::string::npos) << sl_last_error();
  w.fail_after = -1;
  EXPECT_EQ(sl_camera_update(camera, &p, 1, 1.0 / 60, &pose), SL_OK) << sl_last_error();
  // A world that fails at once fails the camera's creation too.
  w.calls = 0;
  w.fail_after = 0;
  sl_camera_settings s;
  sl_camera_settings_default(&s);
  sl_camera* another = nullptr;
  EXPECT_EQ(sl_camera_create(world, &s, &p, 1, 0, &another), SL_ERROR_WORLD);
  EXPECT_EQ(another, nullptr);
  sl_camera_destroy(camera);
  sl_world_destroy(world);
}

TEST(CApi, FilmsAWalkPastAPillarThroughCallbacks) {
  PillarWorld w;
  sl_world* world = callback_world(&w);
  sl_camera* camera = camera_of(world);
  sl_pose pose{};
  int hidden = 0, cuts = 0;
  for (int i = 1; i <= 8 * 60; ++i) {
    const sl_person_state p = walker(i / 60.0);
    ASSERT_EQ(sl_camera_update(camera, &p, 1, 1.0 / 60, &pose), SL_OK) << sl_last_error();
    const sightline::Vec3 cam{pose.position.x, pose.position.y, pose.position.z};
    const sightline::Vec3 look{pose.target.x, pose.target.y, pose.target.z};
    if (!box_oracle::clear(w.boxes, cam, look)) ++hidden;
    cuts += pose.cut;
  }
  EXPECT_EQ(hidden, 0);
  EXPECT_LE(cuts, 1);
  sl_camera_destroy(camera);
  sl_world_destroy(world);
}

TEST(CApi, GeometryWorldAnswersAsTheOracle) {
  const double boxes[] = {-1, 0, -1, 1, 2, 1, 3, 0, 3, 4, 1, 5};
  const double vertices[] = {-5, 0, 8, 5, 0, 8, 0, 5, 8};  // a triangle standing at z = 8
  const uint32_t indices[] = {0, 1, 2};
  sl_world* world = nullptr;
  ASSERT_EQ(sl_world_create_geometry(vertices, 3, indices, 1, boxes, 2, &world), SL_OK);
  std::vector<sightline::Box> oracle{{{-1, 0, -1}, {1, 2, 1}}, {{3, 0, 3}, {4, 1, 5}}};
  int clear = 0;
  ASSERT_EQ(sl_world_line_of_sight(world, {0, 1, -5}, {0, 1, 5}, 0, &clear), SL_OK);
  EXPECT_EQ(clear, 0);
  ASSERT_EQ(sl_world_line_of_sight(world, {0, 3, -5}, {0, 3, 5}, 0, &clear), SL_OK);
  EXPECT_EQ(clear, 1);
  ASSERT_EQ(sl_world_line_of_sight(world, {0, 1, 6}, {0, 1, 10}, 0, &clear), SL_OK);
  EXPECT_EQ(clear, 0);  // the triangle
  double d = 0;
  ASSERT_EQ(sl_world_clearance(world, {0, 1, -3}, 10, 0, &d), SL_OK);
  EXPECT_NEAR(d, box_oracle::distance({0, 1, -3}, oracle[0]), 1e-9);
  ASSERT_EQ(sl_world_clearance(world, {0, 1, 0}, 10, 0, &d), SL_OK);
  EXPECT_LT(d, 0);  // inside a box
  sl_world_destroy(world);
  const double inverted[] = {1, 0, 0, 0, 1, 1};
  EXPECT_EQ(sl_world_create_geometry(nullptr, 0, nullptr, 0, inverted, 1, &world), SL_ERROR_INVALID_ARGUMENT);
  const uint32_t past[] = {0, 1, 9};
  EXPECT_EQ(sl_world_create_geometry(vertices, 3, past, 1, nullptr, 0, &world), SL_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(sl_last_error()).find("vertex 9"), std::string::npos);
  EXPECT_EQ(sl_world_create_geometry(nullptr, 3, nullptr, 0, nullptr, 0, &world), SL_ERROR_INVALID_ARGUMENT);
}

}  // namespace
