// The table of `signalsim compare` (comparison.csv) and its one-screen summary, SUMO-free: built from
// each scenario's route (the sections and lights to compare, in route order) and what its two runs
// left in their directories (summary.json: its metrics, expectations and off_plan).
//
//   items    per scenario: the route's signal sections (turn, roundabout_entry, roundabout_exit;
//            report/signal_sections.hpp, numbered per kind from 1 like results.csv) and its
//            lights (light1, ...), by route s (a light's stop line before a section starting there)
//   rows     per item, one row per driver (signalsim, sumo; with a system under test sut, signalsim,
//            sumo: docs/compare.md): the run's metrics for that item, matched
//            by kind and number (the route is the same, so both runs have the same sections)
//   errors   a run that did not finish gives every item of its scenario an error row for that driver
//            (status error, the message); when no item could be listed, one error row per driver
//   notes    `not reached`; for a SUMO-driven run the stretches it drove off the planned lanes
//            (summary.json off_plan) from the previous section's end (base_link out) to this
//            section's end, or for a light from 2 m past the previous light's line to 2 m past its own;
//            steps off the route
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "map/route_map.hpp"
#include "turn_signal/turn_signal_parameters.hpp"
#include "report/timeline.hpp"

namespace signalsim {

/// A section or a light of a scenario's route.
struct ComparedItem {
  std::string name;                 ///< "turn1", "roundabout_exit1", "light1"
  std::string kind;                 ///< "turn", "roundabout_entry", "roundabout_exit", "light"
  std::string id;                   ///< junction id (sections), light id
  double s = 0.0;                   ///< [m] route s of the section start or the stop line
  double s_end = 0.0;               ///< [m] section end; the stop line for a light
  Blinker blinker = Blinker::None;  ///< the blinker the section asks for (lights: none)
};

/// The route's sections and lights in route order (see the file comment).
std::vector<ComparedItem> compared_items(const RouteMap& route, const TurnSignalParameters& params);

/// What one run (one driver) of a scenario left.
struct DriverRun {
  std::string driver;                ///< "sut" (signalsim with a decider / light judge under test), "signalsim" or "sumo"
  std::string status;                ///< passed, failed, no_expectations, or error
  std::string error;                 ///< why, for status error
  std::string run_dir;               ///< relative to the output directory
  nlohmann::ordered_json summary;    ///< summary.json of a finished run
};

struct ScenarioComparison {
  std::string scenario;              ///< its name
  double base_link_to_front = 0.0;   ///< [m]
  std::vector<ComparedItem> items;
  std::vector<DriverRun> runs;       ///< in driver order: [sut,] signalsim, sumo
};

/// comparison.csv's columns, in order.
const std::vector<std::string>& comparison_columns();

/// Every row (cells in comparison_columns order): scenarios in the given order, items by route s,
/// drivers in run order.
std::vector<std::vector<std::string>> comparison_rows(const std::vector<ScenarioComparison>& scenarios);

/// The whole table as CSV (RFC 4180), header first.
std::string comparison_csv(const std::vector<ScenarioComparison>& scenarios);

/// At most `max_lines` lines, one per item: the drivers side by side (the first scenario's, in order) (lead distance and time, missed
/// and what was shown, stop error or the state at the line), then the errors.
std::string comparison_screen(const std::vector<ScenarioComparison>& scenarios, std::size_t max_lines = 30);

}  // namespace signalsim
