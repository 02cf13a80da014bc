// `sightline kinds`: every registered constraint kind, what it means, its fields and an example.
#include <iostream>

#include "apps/commands.h"
#include "apps/text_table.h"
#include "sightline/csp/kinds/constraint_kinds.h"
#include "sightline/csp/kinds/constraint_entry.h"

namespace sightline::apps {

void add_kinds_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "kinds", "list the constraint kinds problem files can name, with their fields");
  command->callback([] {
    const auto& kinds = csp::ConstraintKinds::global();
    std::string common;
    for (const auto& f : csp::common_constraint_fields()) {
      common += (common.empty() ? "" : ", ") + f;
    }
    std::cout << "Constraint kinds. Besides its own fields, every entry takes the common "
                 "fields: "
              << common << ".\n\n";
    TextTable table;
    table.column("kind").column("fields").column("meaning");
    for (const std::string& name : kinds.names()) {
      const csp::ConstraintKindInfo& info = kinds.get(name, {});
      std::string fields;
      for (const auto& f : info.fields) fields += (fields.empty() ? "" : ", ") + f;
      table.add_row({name, fields.empty() ? "-" : fields, info.description});
    }
    table.print(std::cout);
    // Each kind's example, as a problem file's entry (x1, x2, ... stand for its variables).
    std::cout << "\nExamples:\n";
    for (const std::string& name : kinds.names()) {
      const csp::ConstraintKindInfo& info = kinds.get(name, {});
      std::string scope;
      for (std::size_t i = 0; i < info.example_arity; ++i) {
        scope += (i ? ", x" : "x") + std::to_string(i + 1);
      }
      std::cout << "  - {kind: " << name << ", scope: [" << scope << "]"
                << (info.example.empty() ? "" : ", " + info.example) << "}\n";
    }
  });
}

}  // namespace sightline::apps
