// sumo-gui's view at the ego's first blinker (`run --gui`, gui.png): framed on the junction ahead of
// the ego (and the light ahead, when it is near) instead of the few metres around the tracked ego.
// Through libtraci, as the gui back-end (session_traci.cpp) drives sumo-gui.
#pragma once

#include <string>

#include "session/sumo_session.hpp"

namespace signalsim::sumo {

/// Stops tracking `ego` in `view` and fits the view to hold the ego, the shape of the junction at the end of its lane (or
/// the one it is on) and, when the next light ahead is within 80 m, that light's junction; at least
/// 60 m across, 12 m of margin. Returns what it framed (junction, light, the extent sumo-gui reports
/// it shows); an empty junction and the view unchanged when there is no
/// junction ahead (the route ends). Throws what libtraci throws.
GuiPicture frame_junction_ahead(const std::string& view, const std::string& ego);

}  // namespace signalsim::sumo
