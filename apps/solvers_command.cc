// `sightline solvers`: every registered solver, what it does, and its options.
#include <iostream>

#include "apps/commands.h"
#include "apps/text_table.h"
#include "sightline/solvers/registry.h"

namespace sightline::apps {

void add_solvers_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "solvers", "list the registered solvers with their options (type, default, meaning)");
  command->callback([] {
    const auto& registry = solvers::SolverRegistry::global();
    std::cout << "Solvers (join names with '>' for a pipeline, e.g. 'a>b'; set options with "
                 "--set key=value or --set stage.key=value):\n";
    for (const std::string& name : registry.names()) {
      const solvers::SolverInfo& info = registry.info(name);
      std::cout << '\n' << name << ": " << info.description << '\n';
      if (info.options.empty()) {
        std::cout << "  (no options)\n";
        continue;
      }
      TextTable table;
      table.column("option")
          .column("type")
          .column("default", TextTable::Align::kRight)
          .column("meaning");
      for (const auto& option : info.options) {
        table.add_row({option.name, option.type, option.default_value, option.help});
      }
      table.print(std::cout);
    }
  });
}

}  // namespace sightline::apps
