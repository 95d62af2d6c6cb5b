// `signalsim inspect NET [--route EDGES...]`.
#include <iostream>

#include "app/command.hpp"
#include "app/inspect.hpp"
#include "sumo/route_builder.hpp"

namespace signalsim::app {

Command add_inspect_command(CLI::App& app) {
  auto net_path = std::make_shared<std::string>();
  auto route = std::make_shared<std::vector<std::string>>();
  CLI::App* sub = app.add_subcommand("inspect", "Show the lanelets along a route as the decider sees them");
  sub->add_option("net", *net_path, "SUMO .net.xml (plain or gzip)")->required();
  sub->add_option("--route", *route, "Edge ids of a route");
  return {sub, [net_path, route]() -> int {
            try {
              const auto net = sumo::NetIndex::load(*net_path);
              print_inspection(std::cout, net, *route);
              return 0;
            } catch (const sumo::RouteError& e) {
              return report_bad_input(*net_path + ": --route: " + e.what());
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
