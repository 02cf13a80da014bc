// `sightline view SCENE.yaml --trace A.csv [--trace B.csv ...] --out view.html
// [--assets inline|beside]`: the interactive 3D replay (the one a suite report holds per scene) for any traces in the
// FORMATS.md columns, checked against the scene; experiments/replay/trace_view.h does the work.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "sightline/experiments/replay/trace_view.h"

namespace sightline::apps {
namespace {

struct ViewOptions {
  std::string scene;
  std::vector<std::string> traces;
  std::string out;
  std::string assets = "inline";
  double max_speed = experiments::TraceViewOptions{}.max_speed;
};

void run_view(const ViewOptions& o) {
  experiments::TraceViewOptions options;
  options.scene_path = o.scene;
  options.trace_paths = o.traces;
  options.max_speed = o.max_speed;
  if (o.assets == "beside") {
    // view.html -> view-assets/ beside it, named relative to the page.
    const std::filesystem::path out(o.out);
    const std::string folder = out.stem().string() + "-assets";
    options.replay.assets_dir = (out.parent_path() / folder).string();
    options.replay.assets_href = folder;
  }
  const experiments::TraceView view = experiments::make_trace_view(options);
  const std::string tmp = o.out + ".tmp";
  {
    std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
    file << view.html;
    if (!file) throw std::runtime_error("cannot write '" + tmp + "'");
  }
  std::error_code error;
  std::filesystem::rename(tmp, o.out, error);
  if (error) throw std::runtime_error("cannot write '" + o.out + "': " + error.message());
  std::cout << "Replay of " << view.runs.size() << " trace" << (view.runs.size() == 1 ? "" : "s")
            << " written to " << o.out << " (open it in a browser; " << o.out
            << "#run=<id>&t=<seconds> opens a run paused at a time):\n";
  for (const experiments::TraceViewRunSummary& r : view.runs) {
    std::cout << "  " << r.id << ": " << r.path << ", " << r.frames << " frames, look-at point "
              << "hidden in " << r.hidden_frames << " (independent check), " << r.cuts << " cut"
              << (r.cuts == 1 ? "" : "s") << ", " << r.unflagged_jumps << " unflagged jump"
              << (r.unflagged_jumps == 1 ? "" : "s") << " (faster than "
              << o.max_speed << " m/s without a cut flag)\n";
  }
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Write an interactive 3D replay (HTML) of traces of one scene");
  cmd->add_option("scene", options->scene, "the scene file the traces ran on (YAML)")
      ->required();
  cmd->add_option("--trace", options->traces,
                  "a trace in the FORMATS.md columns (CSV; repeatable, at least one)")
      ->required();
  cmd->add_option("--out", options->out, "the page to write (HTML, one self-contained file)")
      ->required();
  cmd->add_option("--assets", options->assets,
                  "three.js and the scene data: inline (one self-contained page, the default) "
                  "or beside (in OUT-STEM-assets/ next to the page, for big levels)")
      ->check(CLI::IsMember({"inline", "beside"}));
  cmd->add_option("--max-speed", options->max_speed,
                  "m/s: a faster move without a cut flag counts as an unflagged jump "
                  "(default: the chase camera's smooth-motion bound)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->callback([options] { run_view(*options); });
}

}  // namespace sightline::apps
