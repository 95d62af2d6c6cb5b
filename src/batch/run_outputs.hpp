// Reading a run directory back (summary.json, events.csv, timeline.csv), for batch results,
// golden checks and metrics of runs whose summary.json has none.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scenario/scenario.hpp"
#include "report/timeline.hpp"

namespace signalsim {

/// Parses a JSON file. Throws std::runtime_error naming the file.
nlohmann::ordered_json read_json_file(const std::string& path);

/// The whole file as text. Throws std::runtime_error naming the file.
std::string read_text_file(const std::string& path);

/// events.csv rows (time, s_front, kind, from, to, source). Throws std::runtime_error.
std::vector<TimelineEvent> read_events_csv(const std::string& path);

/// timeline.csv rows, by column name (unknown columns ignored). Throws std::runtime_error.
std::vector<TimelineRow> read_timeline_csv(const std::string& path);

/// The "metrics" object for a run directory whose summary.json lacks one: the scenario is loaded
/// with the run's overrides, its route rebuilt from the net, timeline.csv and events.csv read back,
/// and scenario/metrics computes the rest. Throws on any failure.
nlohmann::ordered_json metrics_from_run_dir(const std::string& run_dir, const std::string& scenario_file,
                                            const std::vector<std::string>& set);

}  // namespace signalsim
