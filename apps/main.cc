// sightline: the command-line program. Thin: each subcommand parses its options, calls the
// libraries and prints (see commands.h). Here only the error policy lives: any exception
// from a library becomes "sightline: <message>" on stderr, exit status 2 for bad input or
// usage, 1 for a run that failed its own check; never a crash.
#include <exception>
#include <iostream>

#include "apps/commands.h"
#include "apps/solve_options.h"
#include "apps/solver_registration.h"

int main(int argc, char** argv) {
  namespace apps = sightline::apps;
  // The camera's and composition's solvers and toulbar2 join the one registry, so every
  // command can name them.
  apps::register_all_solvers();
  CLI::App app{"sightline: weighted constraint satisfaction with pluggable solvers"};
  app.name("sightline");
  app.require_subcommand(1);
  apps::add_solve_command(app);
  apps::add_nqueens_command(app);
  apps::add_colour_command(app);
  apps::add_solvers_command(app);
  apps::add_kinds_command(app);
  apps::add_compare_command(app);
  apps::add_run_command(app);
  apps::add_scene_command(app);
  apps::add_follow_command(app);
  apps::add_compose_command(app);
  apps::add_edit_command(app);
  apps::add_convert_command(app);
  apps::add_level_command(app);
  apps::add_view_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help arrives as a ParseError
    std::cerr << "sightline: " << e.what() << " (see --help)\n";
    return 2;
  } catch (const apps::Interrupted& e) {
    std::cout.flush();
    std::cerr << "sightline: " << e.what() << '\n';
    return 130;
  } catch (const apps::RunFailed& e) {
    std::cout.flush();
    std::cerr << "sightline: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "sightline: " << e.what() << '\n';
    return 2;
  } catch (...) {
    std::cout.flush();
    std::cerr << "sightline: an unexpected error of unknown type\n";
    return 2;
  }
  return 0;
}
