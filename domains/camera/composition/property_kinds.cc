#include "sightline/domains/camera/composition/property_kinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace sightline::camera {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegrees = 180.0 / 3.14159265358979323846;

const PersonAtTime& target(const MeasureContext& c, int i) {
  return c.world.people()[static_cast<std::size_t>(c.targets[i])];
}

// [x, y] or [x0, y0, x1, y1] of finite numbers.
std::vector<double> read_numbers(const csp::Spec& field, std::size_t count, const std::string& what) {
  const std::vector<double> v = field.as_numbers(what);
  if (v.size() != count) {
    field.fail("expected " + what + " (" + std::to_string(count) + " numbers), got " +
               std::to_string(v.size()));
  }
  return v;
}

double read_nothing(ShotProperty&, const csp::Spec&) { return 1; }

// A framed property's count when the eight outer samples of `body` (those at 0.1 and 0.9 of
// each side: the corners of the samples' box) settle it: all of them in front and inside
// `rect` -> every sample inside (27); all in front and beyond one edge of it -> none (0).
// Each sample is a mix of the eight, and a view maps a box in front of it to a convex shape
// whose extremes are corners', so the other nineteen land between them. The margins (1e-9
// m of depth, 1e-9 screen units) are far above the rounding of a projection (1e-15), so the
// count is the one the 27 projections give, to the bit. -1 when the corners do not settle it.
int framed_by_outer_samples(const View& view, const Aabb& body, const Eigen::Vector4d& rect) {
  constexpr double kMargin = 1e-9;
  const Eigen::Vector3d lo = body.min + 0.1 * (body.max - body.min);
  const Eigen::Vector3d hi = body.min + 0.9 * (body.max - body.min);
  bool inside = true;
  std::array<bool, 4> beyond{true, true, true, true};  // left, right, below, above
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d q((c & 1) ? hi.x() : lo.x(), (c & 2) ? hi.y() : lo.y(), (c & 4) ? hi.z() : lo.z());
    if (!(view.depth(q) > View::kNearDepth + kMargin)) return -1;
    const std::optional<Eigen::Vector2d> s = view.project(q);
    if (!s) return -1;
    inside = inside && s->x() >= rect[0] + kMargin && s->x() <= rect[2] - kMargin &&
             s->y() >= rect[1] + kMargin && s->y() <= rect[3] - kMargin;
    beyond[0] = beyond[0] && s->x() < rect[0] - kMargin;
    beyond[1] = beyond[1] && s->x() > rect[2] + kMargin;
    beyond[2] = beyond[2] && s->y() < rect[1] - kMargin;
    beyond[3] = beyond[3] && s->y() > rect[3] + kMargin;
  }
  if (inside) return kPersonSamples;
  for (bool b : beyond) {
    if (b) return 0;
  }
  return -1;
}

ShotPropertyKind framed_kind() {
  ShotPropertyKind k;
  k.name = "framed";
  k.description = "fraction of the target's samples in front of the camera and inside rect";
  k.fields = {"rect"};
  k.default_range = ValueRange{1, 1};
  k.read = [](ShotProperty& p, const csp::Spec& entry) {
    if (const csp::Spec* rect = entry.find("rect")) {
      const std::vector<double> r = read_numbers(*rect, 4, "a rectangle [x0, y0, x1, y1] in screen units");
      if (!(r[0] <= r[2]) || !(r[1] <= r[3])) {
        rect->fail("expected a rectangle [x0, y0, x1, y1] with x0 <= x1 and y0 <= y1, got " +
                   rect->preview());
      }
      p.rect = Eigen::Vector4d(r[0], r[1], r[2], r[3]);
    }
    return 1.0;
  };
  k.measure = [](const ShotProperty& p, const MeasureContext& c) {
    if (const int settled = framed_by_outer_samples(c.view, target(c, 0).body, p.rect); settled >= 0) {
      return static_cast<double>(settled) / kPersonSamples;
    }
    int inside = 0;
    for (const Eigen::Vector3d& q : person_samples(target(c, 0).body)) {
      const std::optional<Eigen::Vector2d> s = c.view.project(q);
      if (s && s->x() >= p.rect[0] && s->x() <= p.rect[2] && s->y() >= p.rect[1] &&
          s->y() <= p.rect[3]) {
        ++inside;
      }
    }
    return static_cast<double>(inside) / kPersonSamples;
  };
  return k;
}

ShotPropertyKind screen_position_kind() {
  ShotPropertyKind k;
  k.name = "screen_position";
  k.description = "screen distance between the target's projected aim point and `at`";
  k.fields = {"at"};
  k.default_range = ValueRange{0, 0.02};
  k.read = [](ShotProperty& p, const csp::Spec& entry) {
    const std::vector<double> at = read_numbers(entry.at("at"), 2, "a screen point [x, y]");
    p.at = Eigen::Vector2d(at[0], at[1]);
    return 0.25;
  };
  k.measure = [](const ShotProperty& p, const MeasureContext& c) {
    const std::optional<Eigen::Vector2d> s = c.view.project(target(c, 0).aim);
    return s ? (*s - p.at).norm() : kInf;
  };
  return k;
}

ShotPropertyKind size_kind() {
  ShotPropertyKind k;
  k.name = "size";
  k.description = "projected height, width or area of the target's samples";
  k.fields = {"measure"};
  k.read = [](ShotProperty& p, const csp::Spec& entry) {
    p.measure = "height";
    if (const csp::Spec* m = entry.find("measure")) {
      p.measure = m->as_string("height, width or area");
      if (p.measure != "height" && p.measure != "width" && p.measure != "area") {
        m->fail("expected measure: height, width or area, got " + m->preview());
      }
    }
    return p.measure == "area" ? 0.1 : 0.25;
  };
  k.measure = [](const ShotProperty& p, const MeasureContext& c) {
    Eigen::Vector2d lo(kInf, kInf), hi(-kInf, -kInf);
    for (const Eigen::Vector3d& q : person_samples(target(c, 0).body)) {
      const std::optional<Eigen::Vector2d> s = c.view.project(q);
      if (!s) return kInf;
      lo = lo.cwiseMin(*s);
      hi = hi.cwiseMax(*s);
    }
    const double width = hi.x() - lo.x(), height = hi.y() - lo.y();
    if (p.measure == "width") return width;
    if (p.measure == "area") return width * height;
    return height;
  };
  return k;
}

ShotPropertyKind angle_horizontal_kind() {
  ShotPropertyKind k;
  k.name = "angle_horizontal";
  k.position_only = true;
  k.description = "yaw of (camera - aim point) minus the target's yaw, degrees (0: from the front)";
  k.circular = true;
  k.read = [](ShotProperty&, const csp::Spec&) { return 30.0; };
  k.measure = [](const ShotProperty&, const MeasureContext& c) {
    const PersonAtTime& t = target(c, 0);
    const Eigen::Vector3d v = c.view.position() - t.aim;
    if (v.x() == 0 && v.z() == 0) return kNaN;  // straight above or below: no bearing
    return std::atan2(v.x(), v.z()) * kDegrees - t.yaw;
  };
  return k;
}

ShotPropertyKind angle_vertical_kind() {
  ShotPropertyKind k;
  k.name = "angle_vertical";
  k.position_only = true;
  k.description = "elevation of (camera - aim point) above the horizontal, degrees";
  k.read = [](ShotProperty&, const csp::Spec&) { return 30.0; };
  k.measure = [](const ShotProperty&, const MeasureContext& c) {
    const Eigen::Vector3d v = c.view.position() - target(c, 0).aim;
    return std::atan2(v.y(), std::hypot(v.x(), v.z())) * kDegrees;
  };
  return k;
}

ShotPropertyKind visible_kind() {
  ShotPropertyKind k;
  k.name = "visible";
  k.position_only = true;
  k.description = "fraction of the target's samples whose sight line from the camera is clear";
  k.default_range = ValueRange{1, 1};
  k.read = read_nothing;
  k.measure = [](const ShotProperty&, const MeasureContext& c) {
    return static_cast<double>(c.world.count_clear(c.view.position(), c.targets[0])) / kPersonSamples;
  };
  return k;
}

ShotPropertyKind distance_kind() {
  ShotPropertyKind k;
  k.name = "distance";
  k.position_only = true;
  k.description = "distance from the camera to the target's aim point, metres";
  k.read = read_nothing;
  k.measure = [](const ShotProperty&, const MeasureContext& c) {
    return (c.view.position() - target(c, 0).aim).norm();
  };
  return k;
}

ShotPropertyKind order_kind() {
  ShotPropertyKind k;
  k.name = "order";
  k.description = "B's screen x (or y, or depth) minus A's, at their aim points";
  k.target_count = 2;
  k.fields = {"axis"};
  k.default_range = ValueRange{0, kInf};
  k.read = [](ShotProperty& p, const csp::Spec& entry) {
    p.measure = "horizontal";
    if (const csp::Spec* axis = entry.find("axis")) {
      p.measure = axis->as_string("horizontal, vertical or depth");
      if (p.measure != "horizontal" && p.measure != "vertical" && p.measure != "depth") {
        axis->fail("expected axis: horizontal, vertical or depth, got " + axis->preview());
      }
    }
    return p.measure == "depth" ? 1.0 : 0.1;
  };
  k.measure = [](const ShotProperty& p, const MeasureContext& c) {
    const Eigen::Vector3d& a = target(c, 0).aim;
    const Eigen::Vector3d& b = target(c, 1).aim;
    if (p.measure == "depth") return c.view.depth(b) - c.view.depth(a);
    const std::optional<Eigen::Vector2d> sa = c.view.project(a), sb = c.view.project(b);
    if (!sa || !sb) return kNaN;
    return p.measure == "vertical" ? sb->y() - sa->y() : sb->x() - sa->x();
  };
  return k;
}

}  // namespace

ShotPropertyKinds& ShotPropertyKinds::global() {
  static ShotPropertyKinds* kinds = [] {
    auto* k = new ShotPropertyKinds;
    for (ShotPropertyKind kind : {framed_kind(), screen_position_kind(), size_kind(),
                                  angle_horizontal_kind(), angle_vertical_kind(), visible_kind(),
                                  distance_kind(), order_kind()}) {
      k->add(std::move(kind));
    }
    return k;
  }();
  return *kinds;
}

void ShotPropertyKinds::add(ShotPropertyKind kind) {
  if (kind.name.empty() || !kind.read || !kind.measure) {
    throw std::invalid_argument("a shot property kind needs a name, a read and a measure function");
  }
  if (kinds_.count(kind.name)) {
    throw std::invalid_argument("shot property kind '" + kind.name + "' is registered twice");
  }
  const std::string name = kind.name;
  kinds_.emplace(name, std::move(kind));
}

const ShotPropertyKind* ShotPropertyKinds::find(const std::string& name) const {
  const auto it = kinds_.find(name);
  return it == kinds_.end() ? nullptr : &it->second;
}

std::vector<std::string> ShotPropertyKinds::names() const {
  std::vector<std::string> out;
  for (const auto& [name, kind] : kinds_) out.push_back(name);
  return out;
}

double satisfaction(double q, const ValueRange& range, double softness, bool circular) {
  if (std::isnan(q)) return 0;
  double gap = 0;
  if (circular) {
    if (!std::isfinite(q)) return 0;
    const double lo = range.lo;
    const double hi = range.hi < range.lo ? range.hi + 360 : range.hi;
    if (hi - lo >= 360) return 1;
    const double above = std::fmod(q - lo, 360.0);
    const double at = lo + (above < 0 ? above + 360 : above);  // in [lo, lo + 360)
    if (at <= hi) return 1;
    gap = std::min(at - hi, lo + 360 - at);
  } else {
    if (q >= range.lo && q <= range.hi) return 1;
    gap = q < range.lo ? range.lo - q : q - range.hi;
  }
  return std::max(0.0, 1 - gap / softness);
}

}  // namespace sightline::camera
