// `signalsim schema scenario|sweep`: the JSON Schema (draft-07) of scenario or sweep files, from the
// key tables their loaders read, for editors (docs/schema.md). Deterministic; nothing else printed.
#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "batch/sweep_keys.hpp"
#include "scenario/json_schema.hpp"
#include "scenario/scenario_keys.hpp"

namespace signalsim::app {

Command add_schema_command(CLI::App& app) {
  auto kind = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "schema", "Print the JSON Schema of scenario or sweep files (for editors; docs/schema.md)");
  sub->add_option("kind", *kind, "scenario or sweep")->required()->check(CLI::IsMember({"scenario", "sweep"}));
  return {sub, [kind]() -> int {
            const SchemaJson document = *kind == "scenario"
                                            ? schema_document(scenario_keys(), "signalsim scenario file")
                                            : schema_document(sweep_keys(), "signalsim sweep file");
            std::cout << schema_text(document) << std::flush;
            if (!std::cout) return report_bad_input("schema: cannot write to standard output");
            return 0;
          }};
}

}  // namespace signalsim::app
