// `signalsim countries`: the country presets and their values.
#include <cstdio>

#include "app/command.hpp"
#include "scenario/countries.hpp"

namespace signalsim::app {

Command add_countries_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("countries", "List the country presets (config/countries) and their values");
  return {sub, []() -> int {
            try {
              for (const Country& c : list_countries()) {
                std::printf("%s  %s  (%s)\n", c.code.c_str(), c.name.c_str(), c.path.c_str());
                if (!c.driving_side.empty()) std::printf("    %-52s %s\n", "driving_side", c.driving_side.c_str());
                for (const auto& entry : c.parameters)
                  std::printf("    %-52s %s\n", entry.first.Scalar().c_str(),
                              entry.second.IsScalar() ? entry.second.Scalar().c_str() : "(nested)");
              }
              return 0;
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
