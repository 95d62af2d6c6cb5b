// A sweep's plot: checked before any run starts, so that `sweep --plot` does not fail after every
// run finished: the metric must be a numeric results.csv column some run's route can give, x and y
// swept keys (or `scenario`) that differ.
#pragma once

#include <string>
#include <vector>

#include "batch/run_list.hpp"
#include "batch/run_spec.hpp"
#include "batch/sweep_file.hpp"

namespace signalsim {

/// Why `metric` cannot be the plot: metric of a sweep, "" when it can: it must be a results.csv
/// column that holds numbers - a run metric (max_decel, ...), expectations_passed/_total, wall_time,
/// a section's `<kind><n>.<lead_distance|lead_time|time_on|flickers>` (kind turn, roundabout_entry,
/// roundabout_exit; n from 1) or `light<n>.stop_position_error|red_light_violation|emergency_stop`
/// (the true/false ones as the share of runs where true). Text and the other true/false columns
/// (turn1.blinker, turn1.missed) are refused: a heat map of them shows no value.
std::string plot_metric_problem(const std::string& metric);

/// Checks one plot's x and y against the sweep's swept keys: each is a swept key, `scenario` or
/// empty (signalsim-plot chooses), and they differ. Throws InputError at the line of plot.x / plot.y.
void check_plot_axes(const Sweep& sweep, const SweepPlot& plot);

/// Checks every plot's metric (check_plot_metric) before any run starts.
void check_sweep_plot(const SweepRuns& runs);

/// Checks one plot: metric against the runs before any of them starts: a section or light metric
/// (`roundabout_exit1.lead_distance`, `light2.stop_position_error`) needs a run whose route has that
/// section or light (routes built from the nets as the runs build them; no SUMO). Runs whose route
/// cannot be built are left to fail on their own. Looks at the first kCombinationsChecked runs at
/// most (sweep_check.hpp): beyond them the metric is not refused. Throws InputError at the line of
/// plot.metric.
void check_plot_metric(const SweepPlot& plot, const SweepRuns& runs);

}  // namespace signalsim
