// Fleet mode's files (docs/outputs.md): fleet_events.csv and summary.json's `fleet` section.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "report/fleet_record.hpp"

namespace signalsim {

/// fleet_events.csv: vehicle,time,blinker,s_front,place,place_kind,source (one row per change).
void write_fleet_events_csv(const std::string& path, const FleetRecord& record);

/// summary.json `fleet`: the counts, the places (junctions and roundabouts, by id) and the comparison
/// with SUMO's own blinker when it was measured.
nlohmann::ordered_json fleet_json(const FleetRecord& record);

}  // namespace signalsim
