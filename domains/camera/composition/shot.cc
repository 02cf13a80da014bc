#include "sightline/domains/camera/composition/shot.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sightline/domains/camera/composition/property_kinds.h"
#include "sightline/domains/camera/spec_reading.h"

namespace sightline::camera {
namespace {

using detail::format_number;

// A range end: a finite number or YAML's infinity (.inf, -.inf, +.inf in any of its cases).
double read_bound(const csp::Spec& field, const std::string& what) {
  if (field.type() == csp::Spec::Type::kString) {
    std::string text = field.as_string(what);
    double sign = 1;
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
      sign = text[0] == '-' ? -1 : 1;
      text.erase(0, 1);
    }
    if (text == ".inf" || text == ".Inf" || text == ".INF") {
      return sign * std::numeric_limits<double>::infinity();
    }
  }
  return field.as_number(what + " (a number, or .inf / -.inf)");
}

ValueRange read_range(const csp::Spec& field, const std::string& what, bool circular) {
  const std::vector<csp::Spec>& items = field.items(what + " as [lo, hi]");
  if (items.size() != 2) {
    field.fail("expected " + what + " as [lo, hi] (2 numbers), got a list of " +
               std::to_string(items.size()));
  }
  ValueRange r{read_bound(items[0], "the low end of " + what),
               read_bound(items[1], "the high end of " + what)};
  if (circular) {
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi)) {
      field.fail("expected " + what + " as [lo, hi] in degrees (finite: the arc from lo up to hi, "
                 "through 180 when hi < lo), got " + field.preview());
    }
  } else if (r.lo > r.hi) {
    field.fail("expected " + what + " as [lo, hi] with lo <= hi, got " + field.preview());
  }
  return r;
}

// A lens value: a number, or [lo, hi] the camera may choose in.
ValueRange read_lens(const csp::Spec& field, const std::string& what, double lo, double hi,
                     bool lo_open) {
  ValueRange r;
  if (field.is_list()) {
    r = read_range(field, what, false);
    for (double v : {r.lo, r.hi}) {
      if ((lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi) || (lo_open && v >= hi)) {
        field.fail("expected " + what + " within " + (lo_open ? "(" : "[") + format_number(lo) +
                   ", " + format_number(hi) + (lo_open ? ")" : "]") + ", got " + field.preview());
      }
    }
  } else {
    const double v = field.as_number(what);
    if ((lo_open ? !(v > lo) : !(v >= lo)) || !(v <= hi) || (lo_open && v >= hi)) {
      field.fail("expected " + what + " within " + (lo_open ? "(" : "[") + format_number(lo) +
                 ", " + format_number(hi) + (lo_open ? ")" : "]") + ", got " + field.preview());
    }
    r = {v, v};
  }
  return r;
}

const std::string& read_person(const csp::Spec& field, const std::vector<std::string>& people) {
  const std::string& name = field.as_string("a person's name");
  if (std::find(people.begin(), people.end(), name) == people.end()) {
    std::string known;
    for (const std::string& p : people) known += (known.empty() ? "" : ", ") + p;
    field.fail("unknown person '" + name + "' (the scene's people: " +
               (known.empty() ? "none" : known) + ")");
  }
  return name;
}

ShotProperty read_property(const csp::Spec& entry, const std::vector<std::string>& people) {
  if (!entry.is_map()) {
    entry.fail("expected a property {kind: ..., target: ..., range: [lo, hi], ...}, got " +
               entry.preview());
  }
  const csp::Spec& kind_field = entry.at("kind");
  const std::string& kind_name = kind_field.as_string("a property kind");
  const ShotPropertyKind* kind = ShotPropertyKinds::global().find(kind_name);
  if (!kind) {
    std::string known;
    for (const std::string& n : ShotPropertyKinds::global().names()) {
      known += (known.empty() ? "" : ", ") + n;
    }
    kind_field.fail("unknown shot property kind '" + kind_name + "' (known: " + known + ")");
  }
  std::vector<std::string> keys = kind->fields;
  keys.insert(keys.end(), {"kind", kind->target_count == 1 ? "target" : "targets", "range",
                           "softness", "weight", "hard"});
  entry.check_keys(keys);
  ShotProperty p;
  p.kind = kind_name;
  p.where = entry.where();
  if (kind->target_count == 1) {
    p.targets.push_back(read_person(entry.at("target"), people));
  } else {
    const csp::Spec& list = entry.at("targets");
    const std::vector<csp::Spec>& items = list.items("targets: [A, B]");
    if (items.size() != 2) {
      list.fail("expected targets: [A, B] (2 people), got a list of " +
                std::to_string(items.size()));
    }
    for (const csp::Spec& item : items) p.targets.push_back(read_person(item, people));
  }
  const double default_softness = kind->read(p, entry);
  if (const csp::Spec* range = entry.find("range")) {
    p.range = read_range(*range, "the wanted range of " + kind_name, kind->circular);
  } else if (kind->default_range) {
    p.range = *kind->default_range;
  } else {
    entry.fail("expected range: [lo, hi] (a " + kind_name + " property has no default range)");
  }
  p.softness = default_softness;
  if (const csp::Spec* s = entry.find("softness")) {
    p.softness = detail::read_positive(*s, "the softness");
  }
  if (const csp::Spec* w = entry.find("weight")) p.weight = detail::read_positive(*w, "the weight");
  if (const csp::Spec* h = entry.find("hard")) p.hard = h->as_bool("hard: true or false");
  return p;
}

}  // namespace

std::string ShotProperty::describe() const {
  std::string out = kind + " of ";
  for (std::size_t i = 0; i < targets.size(); ++i) out += (i ? ", " : "") + targets[i];
  if (!measure.empty()) out += " (" + measure + ")";
  return out;
}

std::vector<std::string> Shot::targets() const {
  std::vector<std::string> out;
  for (const ShotProperty& p : properties) {
    for (const std::string& t : p.targets) {
      if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
    }
  }
  return out;
}

Shot read_shot(const csp::Spec& spec, const std::vector<std::string>& people, bool named) {
  if (!spec.is_map()) {
    spec.fail("expected a shot {region: {min: [x, y, z], max: [x, y, z]}, properties: [...], ...}, "
              "got " + spec.preview());
  }
  spec.check_keys({"fov", "aspect", "roll", "region", "clearance", "properties", "name"});
  Shot shot;
  shot.where = spec.where();
  if (named) {
    shot.name = spec.at("name").as_string("the shot's name");
    if (shot.name.empty()) spec.at("name").fail("expected a non-empty shot name");
  } else if (spec.find("name")) {
    spec.at("name").fail("the shot: block takes no name (named shots go in shots:)");
  }
  if (const csp::Spec* f = spec.find("fov")) {
    shot.fov = read_lens(*f, "the vertical field of view (degrees)", 0, 180, true);
  }
  if (const csp::Spec* a = spec.find("aspect")) {
    shot.aspect = detail::read_positive(*a, "the aspect (image width / height)");
  }
  if (const csp::Spec* r = spec.find("roll")) {
    shot.roll = read_lens(*r, "the roll (degrees)", -180, 180, false);
  }
  const csp::Spec& region = spec.at("region");
  if (!region.is_map()) region.fail("expected region: {min: [x, y, z], max: [x, y, z]}");
  region.check_keys({"min", "max"});
  shot.region.min = detail::read_vector3(region.at("min"), "the region's min corner");
  shot.region.max = detail::read_vector3(region.at("max"), "the region's max corner");
  for (int i = 0; i < 3; ++i) {
    if (!(shot.region.min[i] < shot.region.max[i])) {
      region.fail("expected a region with min < max on every axis (a volume the camera may stand "
                  "in), got min " + region.at("min").preview() + ", max " +
                  region.at("max").preview());
    }
  }
  if (const csp::Spec* c = spec.find("clearance")) {
    shot.clearance = detail::read_non_negative(*c, "the clearance (metres)");
  }
  const csp::Spec& properties = spec.at("properties");
  for (const csp::Spec& entry : properties.items("a list of properties")) {
    shot.properties.push_back(read_property(entry, people));
  }
  if (shot.properties.empty()) {
    properties.fail("expected at least one property: a shot frames someone");
  }
  return shot;
}

std::vector<ScriptEntry> read_script(const csp::Spec& spec, const std::vector<std::string>& people) {
  std::vector<ScriptEntry> script;
  for (const csp::Spec& entry : spec.items("a list of script entries")) {
    if (!entry.is_map()) {
      entry.fail("expected a script entry {t: [t0, t1], speaker: A, to: B} or {t: [t0, t1], "
                 "action: A}, got " + entry.preview());
    }
    ScriptEntry e;
    e.where = entry.where();
    const csp::Spec& t = entry.at("t");
    const std::vector<double> times = t.as_numbers("the interval [t0, t1] (seconds)");
    if (times.size() != 2 || !(times[0] < times[1])) {
      t.fail("expected the interval [t0, t1] with t0 < t1, got " + t.preview());
    }
    e.t0 = times[0];
    e.t1 = times[1];
    if (entry.find("action")) {
      entry.check_keys({"t", "action"});
      e.action = read_person(entry.at("action"), people);
    } else {
      entry.check_keys({"t", "speaker", "to"});
      e.speaker = read_person(entry.at("speaker"), people);
      e.to = read_person(entry.at("to"), people);
      if (e.to == e.speaker) entry.at("to").fail("a line is spoken to someone else than its speaker");
    }
    if (!script.empty() && e.t0 < script.back().t0) {
      t.fail("script entries go in time order: this one starts before the one on line " +
             std::to_string(script.back().where.line));
    }
    if (!e.speaker.empty()) {
      for (const ScriptEntry& other : script) {
        if (other.speaker == e.speaker && e.t0 < other.t1 && other.t0 < e.t1) {
          t.fail(e.speaker + "'s line overlaps their line on line " +
                 std::to_string(other.where.line) + ": one person's lines may not overlap");
        }
      }
    }
    script.push_back(std::move(e));
  }
  return script;
}

}  // namespace sightline::camera
