// `signalsim schema scenario|sweep`: the JSON Schema (draft-07) of scenario or sweep files, from the
// key tables their loaders read, for editors (docs/schema.md); `decider-request|decider-reply|
// light-judge-request|light-judge-reply`: the JSON-lines protocol of an exec: SUT (docs/decider.md).
// Deterministic; nothing else printed.
#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "batch/sweep_keys.hpp"
#include "scenario/json_schema.hpp"
#include "scenario/scenario_keys.hpp"
#include "sut/sut_schemas.hpp"

namespace signalsim::app {

Command add_schema_command(CLI::App& app) {
  auto kind = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "schema", "Print the JSON Schema of scenario or sweep files (for editors; docs/schema.md) or of the "
                "JSON-lines messages of an exec: decider or light judge (docs/decider.md)");
  sub->add_option("kind", *kind,
                  "scenario, sweep, decider-request, decider-reply, light-judge-request or light-judge-reply")
      ->required()
      ->check(CLI::IsMember({"scenario", "sweep", "decider-request", "decider-reply", "light-judge-request",
                             "light-judge-reply"}));
  return {sub, [kind]() -> int {
            const std::string role = kind->rfind("decider", 0) == 0 ? "decider" : "light_judge";
            if (kind->ends_with("-request")) {
              std::cout << sut_request_schema(role) << std::flush;
            } else if (kind->ends_with("-reply")) {
              std::cout << sut_reply_schema(role) << std::flush;
            } else {
              const SchemaJson document = *kind == "scenario"
                                              ? schema_document(scenario_keys(), "signalsim scenario file")
                                              : schema_document(sweep_keys(), "signalsim sweep file");
              std::cout << schema_text(document) << std::flush;
            }
            if (!std::cout) return report_bad_input("schema: cannot write to standard output");
            return 0;
          }};
}

}  // namespace signalsim::app
