// The editor on long conversations: the editing model's size and each solver's time and cost
// on generated conversations (experiments/sources/conversation_generator.h), one per layout
// (standing, walking, circling, someone comes in), 5 minutes each by default.
//
// For each conversation: the footage (every candidate shot composed at every slot: the
// time a user waits before any solver runs), the model (slots, candidate shots, constraints,
// entries of the cut tables), and per solver the model's cost, the solve time, how it
// stopped, and the edit judged by experiments/runs/edit_metrics.h. Printed as Markdown.
//
//   build/bench/edit_bench [--seconds S] [--layouts 0,1,2,3] [--seed N] [--time-limit S]
//                          [--solvers chain,greedy,bnb,tabu,lns,sls] [--write DIR]
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "sightline/domains/camera/editing/editor.h"
#include "sightline/experiments/runs/edit_metrics.h"
#include "sightline/experiments/runs/edit_run.h"
#include "sightline/experiments/sources/conversation_generator.h"

int main(int argc, char** argv) {
  using namespace sightline;
  CLI::App app("the editor on long generated conversations");
  double seconds = 300, time_limit = 10;
  std::uint64_t seed = 1;
  std::vector<int> layouts = {0, 1, 2, 3};
  std::vector<std::string> solver_names = {"chain", "greedy", "bnb", "tabu", "lns", "sls"};
  std::string write;
  app.add_option("--seconds", seconds, "length of each conversation (default 300)");
  app.add_option("--layouts", layouts, "layouts: 0 standing, 1 walking, 2 circling, 3 someone comes in")
      ->delimiter(',');
  app.add_option("--seed", seed, "the generator's seed");
  app.add_option("--time-limit", time_limit, "seconds per solver (default 10)");
  app.add_option("--solvers", solver_names, "editors to run")->delimiter(',');
  app.add_option("--write", write, "write each conversation's scene file (YAML) into this folder");
  CLI11_PARSE(app, argc, argv);
  static const char* kLayout[] = {"standing", "walking", "circling", "comes in"};
  std::printf("| conversation | slots x shots | constraints | footage s | solver | cost | solve s | stop | "
              "crossings | jump cuts | short | cuts/min | speaker shown %% | readable %% |\n");
  std::printf("| --- | ---: | ---: | ---: | --- | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
  for (const int layout : layouts) {
    experiments::ConversationOptions o;
    o.seed = seed;
    o.seconds = seconds;
    o.layout = layout;
    const camera::Scene scene = experiments::generate_conversation(o);
    if (!write.empty()) {
      std::ofstream(write + "/" + scene.name() + "-" + std::to_string(layout) + ".yaml")
          << experiments::conversation_yaml(o);
    }
    camera::EditorOptions options;
    options.time_limit_seconds = time_limit;
    const camera::Footage footage =
        camera::film_footage(scene, camera::candidate_shots(scene), options.footage);
    for (const std::string& name : solver_names) {
      options.solver = name;
      const camera::Edit edit = camera::edit_footage(scene, footage, options);
      const auto rows = experiments::edit_trace(scene, edit);
      const experiments::EditMetrics m = experiments::edit_metrics(scene, rows, options.weights.min_shot_seconds);
      // How the solver stopped: the report's "stop: ..." up to any detail in brackets.
      std::string stop = "-";
      if (const auto at = edit.solver_message.rfind("stop: "); name != camera::kGreedyEditor && at != std::string::npos) {
        stop = edit.solver_message.substr(at + 6);
        stop = stop.substr(0, stop.find(" ("));
      }
      std::printf("| %s %s | %zu x %zu | %zu | %.2f | %s | %.2f | %.3f | %s | %d | %d | %d | %.1f | %.1f | %.1f |\n",
                  scene.name().c_str(), kLayout[layout], edit.costs.slots, edit.costs.shots,
                  edit.model_constraints, footage.seconds, name.c_str(), edit.score.soft,
                  edit.solve_seconds, stop.c_str(), m.line_crossings, m.jump_cuts, m.short_shots,
                  m.cuts_per_minute, m.speaker_shown_percent, m.speaker_readable_percent);
      std::fflush(stdout);
    }
  }
  return 0;
}
