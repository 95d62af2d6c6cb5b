// The metrics as results.csv columns: summary.json's "metrics" object flattened to one cell per
// scalar, and the fixed order of those columns.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace signalsim {

/// One results.csv cell per scalar: run-level keys as they are ("max_decel"), section fields as
/// "<kind><n>.<field>" (n counts sections of that kind from 1: "turn1.lead_distance",
/// "roundabout_exit1.missed"), light fields as "light<n>.<field>". Nulls are left out; numbers use
/// the JSON text, booleans true/false.
std::vector<std::pair<std::string, std::string>> flatten_metrics(const nlohmann::ordered_json& metrics);

/// A fixed order of flattened metric columns, independent of which runs have which: run-level
/// keys first (a SUT's decider, decider_agreement, light_judge, light_judge_agreement before the
/// metrics), then turns, roundabout entries, exits, other sections, lights; by number, then field.
bool metric_column_less(const std::string& a, const std::string& b);

/// Whether `name` is a run-level metric's column (max_decel, max_jerk, p95_decel, ..., a SUT's
/// agreement); not the SUT's name columns (decider, light_judge), which a swept SUT shares.
bool is_run_metric_column(const std::string& name);

}  // namespace signalsim
