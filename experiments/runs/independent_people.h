// IndependentPeople: where the scene's people are and how a camera sees them, computed for
// the judges (shot_metrics, edit_metrics) from the scene's keyframes and FORMATS.md's
// definitions alone -- its own box placement, projection and sight-line test (and
// IndependentTriangles for a level), sharing no code with the composition or the editor,
// so a judge never trusts the code it judges.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <vector>

#include "sightline/domains/camera/scene.h"
#include "sightline/experiments/runs/independent_triangles.h"

namespace sightline::experiments {

// A camera as a trace row gives it.
struct JudgedCamera {
  Eigen::Vector3d position, target;
  double fov = 50, roll = 0, aspect = 16.0 / 9.0;
};

// How one person looks from a camera (FORMATS.md's 27 samples).
struct PersonSeen {
  bool found = false;   // the scene has this person
  int framed = 0;       // samples in front and inside the image
  int seen = 0;         // samples no solid, mover or other person hides
  int framed_and_seen = 0;
  bool head = false;    // the head sample (0.5, 0.9, 0.5) framed and seen
  double height = 0;    // max sy - min sy over the samples (0 when one is not in front)
  double bearing = 0;   // degrees: the camera's direction from their aim point minus their yaw, in [-180, 180)
};

class IndependentPeople {
 public:
  explicit IndependentPeople(const camera::Scene& scene);
  // Everyone's box at t.
  void set_time(double t);
  PersonSeen look(const JudgedCamera& camera, const std::string& name) const;
  // The person's aim point (feet + look_at_height) at the current time; NaN if unknown.
  Eigen::Vector3d aim(const std::string& name) const;

 private:
  struct Box {
    Eigen::Vector3d lo, hi;
  };
  struct Person {
    std::string name;
    Eigen::Vector3d size;
    double look_at_height = 1.5;
    const camera::Trajectory* path = nullptr;
    int box = -1;      // into boxes_
    double yaw = 0;
    Eigen::Vector3d feet = Eigen::Vector3d::Zero();
  };
  static bool passes_through(const Box& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
  const camera::Scene* scene_;
  std::vector<Box> boxes_;
  std::vector<int> owner_;  // per box: its person, or -1
  std::vector<Person> people_;
  std::unique_ptr<IndependentTriangles> triangles_;
};

}  // namespace sightline::experiments
