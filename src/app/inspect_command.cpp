// `signalsim inspect NET [--route EDGES...] [--country CODE] [--set NAME=VALUE...]`.
#include <iostream>
#include <optional>

#include "app/command.hpp"
#include "app/inspect.hpp"
#include "scenario/countries.hpp"
#include "step/route_planning.hpp"
#include "route/route_builder.hpp"

namespace signalsim::app {
namespace {

struct InspectOptions {
  std::string net_path;
  std::vector<std::string> route;
  std::string country;
  std::vector<std::string> set;
};

int inspect(const InspectOptions& o) {
  try {
    const auto net = sumo::NetIndex::load(o.net_path, sumo::NetReading::Whole);  // its summary lists every defect
    // Everything is built before anything is printed: bad input writes no partial output.
    std::optional<sumo::RoutePlan> plan;
    if (!o.route.empty()) {
      // Parameters that change lanelet attributes (the exit-signal marking) as a scenario would set them.
      ParameterSet params;
      if (!o.country.empty()) {
        const Country country = load_country(o.country);
        params.apply(country.parameters, country.path);
      }
      YAML::Node overrides;
      for (const std::string& item : o.set) {
        const auto eq = item.find('=');
        if (eq == std::string::npos || eq == 0) return report_bad_input("--set: '" + item + "' is not of the form name=value");
        overrides[item.substr(0, eq)] = YAML::Load(item.substr(eq + 1));
      }
      if (overrides.size() > 0) params.apply(overrides, "--set");
      params.check_consistency("--set");
      plan = prepare_route(sumo::build_route(net, o.route), run_parameters(params).decider);
    }
    print_net_summary(std::cout, net);
    if (plan) print_route(std::cout, *plan);
    return 0;
  } catch (const sumo::NetDefectError& e) {
    return report_bad_input(std::string(e.what()) + " in --route");
  } catch (const sumo::RouteError& e) {
    return report_bad_input(o.net_path + ": --route: " + e.what());
  } catch (const std::exception& e) {
    return report_bad_input(e.what());
  }
}

}  // namespace

Command add_inspect_command(CLI::App& app) {
  auto options = std::make_shared<InspectOptions>();
  CLI::App* sub = app.add_subcommand("inspect", "Show the lanelets along a route as the decider sees them");
  sub->add_option("net", options->net_path, "SUMO .net.xml (plain or gzip)")->required();
  sub->add_option("--route", options->route, "Edge ids of a route (space- or comma-separated)")->delimiter(',');
  sub->add_option("--country", options->country, "Apply a country preset (e.g. jp: exit-signal marking)");
  sub->add_option("--set", options->set, "Parameter override name=value; repeatable");
  return {sub, [options] { return inspect(*options); }};
}

}  // namespace signalsim::app
