#include "sightline/domains/camera/profile_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "sightline/csp/files/yaml_spec.h"
#include "sightline/domains/camera/profile_presets.h"
#include "sightline/domains/camera/spec_reading.h"

namespace sightline::camera {
namespace {

using csp::Spec;
using detail::read_in_range;
using detail::read_non_negative;
using detail::read_positive;

// Presets may name a base themselves; this bounds the chain (and catches cycles).
constexpr int kMaxBaseDepth = 8;

CameraProfile parse_onto(const Spec& spec, const std::string& fallback_name, int depth);

void read_desired(const Spec* block, DesiredValue& value, const std::string& name,
                  const std::string& desired_what, double lo, double hi) {
  if (block == nullptr) return;
  block->check_keys({"desired", "weight"});
  if (const Spec* d = block->find("desired")) {
    value.desired = read_in_range(*d, name + ".desired (" + desired_what + ")", lo, hi);
  }
  if (const Spec* w = block->find("weight")) {
    value.weight = read_non_negative(*w, name + ".weight");
  }
}

AreaAdaptation read_adaptation(const Spec& block, const std::string& kind) {
  AreaAdaptation a;
  if (block.is_null()) return a;  // "enclosed:" with nothing: no adaptation
  block.check_keys({"ceiling_margin", "distance_fraction"});
  if (const Spec* m = block.find("ceiling_margin")) {
    a.ceiling_margin = read_non_negative(*m, "areas." + kind + ".ceiling_margin (metres)");
  }
  if (const Spec* f = block.find("distance_fraction")) {
    a.distance_fraction = read_in_range(
        *f, "areas." + kind + ".distance_fraction (of the area's smaller width)", 0, 1, true);
  }
  return a;
}

CameraProfile load_preset(const std::string& name, const csp::SourceLocation& where, int depth) {
  const std::string canonical = canonical_preset(name);
  for (const auto& preset : detail::preset_texts()) {
    if (canonical == preset.name) {
      return parse_onto(csp::parse_yaml(preset.yaml, std::string("preset ") + preset.name),
                        preset.name, depth + 1);
    }
  }
  std::string known;
  for (const auto& n : preset_names()) known += (known.empty() ? "" : ", ") + n;
  throw csp::InputError(where, "unknown camera profile '" + name + "' (presets: " + known +
                                   "; or give a .yaml file or an inline mapping)");
}

CameraProfile base_profile(const Spec& spec, int depth) {
  const Spec* base = spec.find("base");
  if (base == nullptr) return CameraProfile{};
  const std::string& name = base->as_string("a preset name for 'base'");
  if (depth >= kMaxBaseDepth) base->fail("profile bases nest too deeply (a cycle?)");
  return load_preset(name, base->where(), depth);
}

CameraProfile parse_onto(const Spec& spec, const std::string& fallback_name, int depth) {
  if (!spec.is_map()) spec.fail("expected a camera profile (a mapping), got " + spec.preview());
  spec.check_keys({"name", "description", "base", "height", "distance", "orientation",
                   "frame_coherence", "occlusion", "clearance", "search", "areas", "sensing",
                   "anticipation", "cuts", "extras"});
  CameraProfile p = base_profile(spec, depth);
  p.name = spec.find("name") ? spec.at("name").as_string("a profile name") : fallback_name;
  if (const Spec* d = spec.find("description")) p.description = d->as_string("a description");

  read_desired(spec.find("height"), p.height, "height", "metres above the feet", -1e6, 1e6);
  read_desired(spec.find("distance"), p.distance, "distance", "horizontal metres", 0, 1e6);
  read_desired(spec.find("orientation"), p.orientation, "orientation", "degrees", 0, 180);
  if (const Spec* fc = spec.find("frame_coherence")) {
    fc->check_keys({"weight"});
    if (const Spec* w = fc->find("weight")) {
      p.frame_coherence_weight = read_non_negative(*w, "frame_coherence.weight");
    }
  }
  if (const Spec* occ = spec.find("occlusion")) {
    occ->check_keys({"look_at_hard", "look_at_weight", "visible_fraction_weight"});
    if (const Spec* h = occ->find("look_at_hard")) p.look_at_hard = h->as_bool();
    if (const Spec* w = occ->find("look_at_weight")) {
      p.look_at_weight = read_non_negative(*w, "occlusion.look_at_weight");
    }
    if (const Spec* w = occ->find("visible_fraction_weight")) {
      p.visible_fraction_weight = read_non_negative(*w, "occlusion.visible_fraction_weight");
    }
  }
  if (const Spec* cl = spec.find("clearance")) {
    cl->check_keys({"radius", "hard", "weight"});
    if (const Spec* r = cl->find("radius")) {
      p.clearance_radius = read_non_negative(*r, "clearance.radius (metres)");
    }
    if (const Spec* h = cl->find("hard")) p.clearance_hard = h->as_bool();
    if (const Spec* w = cl->find("weight")) p.clearance_weight = read_non_negative(*w, "clearance.weight");
  }
  if (const Spec* search = spec.find("search")) {
    search->check_keys({"half_size"});
    if (const Spec* h = search->find("half_size")) {
      p.search_half_size = read_positive(*h, "search.half_size (metres)");
    }
  }
  if (const Spec* areas = spec.find("areas")) {
    areas->check_keys({"enclosed", "semi-enclosed"});
    if (const Spec* e = areas->find("enclosed")) p.enclosed = read_adaptation(*e, "enclosed");
    if (const Spec* s = areas->find("semi-enclosed")) {
      p.semi_enclosed = read_adaptation(*s, "semi-enclosed");
    }
  }
  if (const Spec* sensing = spec.find("sensing")) {
    sensing->check_keys({"enabled", "ceiling_probe", "behind_probe", "wall_margin",
                         "min_distance", "smoothing"});
    SpaceSensing& z = p.sensing;
    if (const Spec* e = sensing->find("enabled")) z.enabled = e->as_bool();
    if (const Spec* v = sensing->find("ceiling_probe")) {
      z.ceiling_probe = read_positive(*v, "sensing.ceiling_probe (metres)");
    }
    if (const Spec* v = sensing->find("behind_probe")) {
      z.behind_probe = read_positive(*v, "sensing.behind_probe (metres)");
    }
    if (const Spec* v = sensing->find("wall_margin")) {
      z.wall_margin = read_non_negative(*v, "sensing.wall_margin (metres)");
    }
    if (const Spec* v = sensing->find("min_distance")) {
      z.min_distance = read_non_negative(*v, "sensing.min_distance (metres)");
    }
    if (const Spec* v = sensing->find("smoothing")) {
      z.smoothing = read_non_negative(*v, "sensing.smoothing (seconds)");
    }
  }
  if (const Spec* block = spec.find("anticipation")) {
    block->check_keys({"lookahead", "horizon", "samples", "weight", "decay", "plan_seconds",
                      "max_jerk"});
    Anticipation& a = p.anticipation;
    if (const Spec* v = block->find("lookahead")) {
      const std::string& text = v->as_string("a lookahead mode: none, motion or path");
      const auto mode = lookahead_from_string(text);
      if (!mode) v->fail("expected anticipation.lookahead: none, motion or path, got '" + text + "'");
      a.lookahead = *mode;
    }
    if (const Spec* v = block->find("horizon")) {
      a.horizon = read_in_range(*v, "anticipation.horizon (seconds ahead)", 0, 5, true);
    }
    if (const Spec* v = block->find("samples")) {
      const double n = read_in_range(*v, "anticipation.samples (predicted points)", 1,
                                     Anticipation::kMaxSamples);
      if (n != std::floor(n)) v->fail("expected anticipation.samples, a whole number, got " + v->preview());
      a.samples = static_cast<int>(n);
    }
    if (const Spec* v = block->find("weight")) a.weight = read_non_negative(*v, "anticipation.weight");
    if (const Spec* v = block->find("decay")) a.decay = read_positive(*v, "anticipation.decay (seconds)");
    if (const Spec* v = block->find("plan_seconds")) {
      a.plan_seconds = read_in_range(*v, "anticipation.plan_seconds (seconds, 0 = off)", 0, 5);
    }
    if (const Spec* v = block->find("max_jerk")) {
      a.max_jerk = read_in_range(*v, "anticipation.max_jerk (m/s^3, 0 = unbounded)", 0, 1e5);
    }
  }
  if (const Spec* block = spec.find("cuts")) {
    block->check_keys({"leave_enclosed", "backing_up", "stuck", "smooth_escape", "cut_ahead",
                       "stuck_per_minute"});
    if (const Spec* v = block->find("leave_enclosed")) p.cuts.leave_enclosed = v->as_bool();
    if (const Spec* v = block->find("backing_up")) p.cuts.backing_up = v->as_bool();
    if (const Spec* v = block->find("stuck")) p.cuts.stuck = v->as_bool();
    if (const Spec* v = block->find("smooth_escape")) p.cuts.smooth_escape = v->as_bool();
    if (const Spec* v = block->find("cut_ahead")) p.cuts.cut_ahead = v->as_bool();
    if (const Spec* v = block->find("stuck_per_minute")) {
      const long long n = v->as_integer("a whole number of cuts in [0, 16]");
      if (n < 0 || n > 16) v->fail("expected stuck_per_minute in [0, 16] (0: no limit), got " + std::to_string(n));
      p.cuts.stuck_per_minute = static_cast<int>(n);
    }
  }
  if (const Spec* extras = spec.find("extras")) {
    for (const Spec& entry : extras->items("a list of constraint entries for 'extras'")) {
      if (!entry.is_map()) {
        entry.fail("expected a constraint entry {kind: ..., scope: [cam_y], ...}, got " +
                   entry.preview());
      }
      p.extras.push_back(entry);
    }
  }
  if (const std::string error = p.validate(); !error.empty()) spec.fail(error);
  return p;
}

}  // namespace

CameraProfile parse_profile(const csp::Spec& spec, const std::string& fallback_name) {
  return parse_onto(spec, fallback_name, 0);
}

CameraProfile read_profile_file(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  return parse_profile(csp::read_yaml_file(path), stem);
}

std::vector<std::string> preset_names() {
  std::vector<std::string> names;
  for (const auto& preset : detail::preset_texts()) names.emplace_back(preset.name);
  std::sort(names.begin(), names.end());
  return names;
}

std::string canonical_preset(const std::string& name) {
  if (name == "default") return kDefaultPreset;
  if (name == "thesis") return "thesis-default";
  return name;
}

bool is_preset(const std::string& name) {
  if (name == "default" || name == "thesis") return true;
  for (const auto& preset : detail::preset_texts()) {
    if (name == preset.name) return true;
  }
  return false;
}

CameraProfile preset_profile(const std::string& name, const csp::SourceLocation& where) {
  return load_preset(name, where, 0);
}

CameraProfile resolve_profile(const csp::Spec& value, const std::string& base_dir,
                              std::string& source) {
  if (value.is_map()) {
    source = "inline";
    return parse_profile(value, "inline");
  }
  const std::string& text = value.as_string("a profile: a preset name, a .yaml file or a mapping");
  if (is_preset(text)) {
    source = "preset " + canonical_preset(text);
    return preset_profile(text, value.where());
  }
  const std::filesystem::path path(text);
  const std::string ext = path.extension().string();
  if (ext == ".yaml" || ext == ".yml") {
    const std::filesystem::path full =
        path.is_absolute() || base_dir.empty() ? path : std::filesystem::path(base_dir) / path;
    if (!std::filesystem::exists(full)) {
      value.fail("profile file '" + full.string() + "' does not exist");
    }
    source = "file " + full.string();
    return read_profile_file(full.string());
  }
  return preset_profile(text, value.where());  // throws, listing the presets
}

}  // namespace sightline::camera
