// sumo-gui's view at the ego's first blinker (`run --gui`, gui.png): framed on the junction ahead of
// the ego (and the light ahead, when it is near) instead of the few metres around the tracked ego.
// Through libtraci, as the gui back-end (session_traci.cpp) drives sumo-gui.
#pragma once

#include <optional>
#include <string>

#include "session/sumo_session.hpp"

namespace signalsim::sumo {

/// When the junction at the end of the ego's lane (or the one it is on) is within 40 m of the ego
/// (its centre): keeps `view` tracking `ego` and zooms it to hold, about the ego, that junction's
/// shape and, when the next light ahead is within 80 m, that light's junction; at least 60 m across,
/// 12 m of margin. Returns what it framed (junction, light, the extent sumo-gui reports it shows,
/// about the ego); nullopt and the view unchanged when no junction is ahead or it is farther.
/// Throws what libtraci throws.
std::optional<GuiPicture> frame_junction_ahead(const std::string& view, const std::string& ego);

}  // namespace signalsim::sumo
