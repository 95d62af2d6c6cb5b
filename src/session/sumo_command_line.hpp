// SUMO's command line for a session (embedded libsumo and a sumo-gui signalsim starts), and reading
// SUMO's first error line out of what it printed. Pure functions: no SUMO.
#pragma once

#include <string>
#include <vector>

#include "session/sumo_session.hpp"

namespace signalsim::sumo {

/// `binary` followed by SUMO's options for `config` (docs/behaviour.md §S1): the net, route and additional
/// files, step length, begin, seed, collisions as warnings, no teleporting, SUMO's messages to
/// config.log_file, the sublane model or the continuous lane change when asked for, then config.extra_args. The options signalsim
/// sets by default and a user may replace (`time-to-teleport`, `no-step-log`, `duration-log.disable`,
/// `lateral-resolution`, `lanechange.duration`)
/// are left out when extra_args gives them (SUMO refuses an option given twice).
std::vector<std::string> sumo_command_line(const SessionConfig& config, const std::string& binary);

/// SUMO's first "Error: " message without the prefix, its continuation lines (starting with a blank)
/// joined to it with one blank (else the first non-empty line that is not a warning) of `text`.
std::string first_error_line(const std::string& text);

}  // namespace signalsim::sumo
