// The SUMO-driven run (`signalsim run S --driver sumo`, docs/compare.md): SUMO drives the ego on its own and
// signalsim only observes, into the same RunRecord drive() fills, so that metrics and expectations
// measure both drivers with the same code. The ego is inserted exactly as for drive() (route, depart
// lane/pos/speed, vType, seed, traffic, light offsets: RunContext::sumo_drives), then nothing is
// commanded: no speed, signals, lane changes or speed mode (SUMO's defaults, docs/behaviour.md §S5).
//
//   loop until the ego arrives or `duration` simulated seconds have passed:
//     observe  the ego's lane, lane position, speed and SUMO's signal mask, at the same moment
//     locate   route s of the front (rules below); steps off the planned lanes are recorded
//     blinker  SUMO's mask decoded: the hazard bit, or left and right together, is hazard; else left
//              or right; blinker_source "sumo"; sumo_signals is that same mask
//     lights   the nearest light not passed by more than 2 m: its id and the ego's link state
//     stop     the first step at rest (< 0.01 m/s) with the front on that light's approach lanelet
//              while its link shows r, u, y or Y: the rest position against the stop point the judge
//              would use (stop line - stop_margin, docs/behaviour.md §L9.2); a new stop only after moving again
//     red      the front crosses a stop line (+5 cm) during a step that began with its link r or u
//     step     SUMO advances one step
//
// Locating the front: SUMO changes lanes on its own, so the ego may be on a lane the lane plan does
// not list. A planned lane gives its route s. Another lane of a route edge gives that edge's route
// lanelet s plus the lane position (the lanes of an edge share its length). An internal lane of
// another connection of a route junction gives the s of the junction's route lanelet the front is on
// (or the junction's first one ahead) plus the lane position, at most that lanelet's end, and never
// less than the previous step's s: the two connections differ in length, and the position must
// neither go back nor run past the junction. Both count as off the plan (RunRecord::off_plan). Any other lane is off the route: s is held and
// the step counted (off_route_steps), as in drive().
#pragma once

#include <optional>
#include <string>

#include "sim/session_setup.hpp"
#include "report/timeline.hpp"
#include "net/net_index.hpp"

namespace signalsim {

/// Where the front is on the route (the locating rules of the file comment).
struct RoutePosition {
  std::optional<double> s;  ///< route s of the front; empty: off the route
  bool on_plan = false;     ///< the lane is the lane plan's lanelet there
};
/// `hint`: the route index the front was on at the previous step; `last_s`: its s then.
RoutePosition locate_on_route(const RouteMap& route, const std::string& lane, const std::string& edge, double lane_pos,
                              std::size_t hint, double last_s);

/// Observes a run started with RunContext::sumo_drives (see the file comment). Throws
/// sumo::SumoError when SUMO fails.
RunRecord observe_sumo_drive(const StartedRun& run, const sumo::NetIndex& net);

}  // namespace signalsim
