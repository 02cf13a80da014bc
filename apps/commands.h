// The subcommands of the `sightline` program, one file each (apps/<name>_command.cc).
//
// Each add_<name>_command declares its subcommand, its options and the callback that runs
// it on the given CLI11 app. Adding a command is one new file, one declaration here and one
// line in main.cc. Callbacks report bad input by throwing (csp::InputError,
// solvers::OptionError, ...) and a failed run by throwing RunFailed; main turns both into a
// message and an exit status.
#pragma once

#include <CLI/CLI.hpp>

namespace sightline::apps {

void add_solve_command(CLI::App& app);
void add_nqueens_command(CLI::App& app);
void add_colour_command(CLI::App& app);
void add_solvers_command(CLI::App& app);
void add_kinds_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_scene_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_follow_command(CLI::App& app);
void add_compose_command(CLI::App& app);
void add_edit_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_level_command(CLI::App& app);
void add_view_command(CLI::App& app);

}  // namespace sightline::apps
