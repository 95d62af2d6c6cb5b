// What happened at each light of a run: every signalised approach on the route (stop line =
// approach lane end - stopOffset), measured from the rows between the previous light's stop line
// and this one's:
//
//   state_at_line        the ego link's state as the front crossed the stop line
//   red_light_violation  crossed at r/u (or the run recorded a violation there)
//   decision             the judge's most restrictive decision on the approach
//                        (emergency_stop > stop > pass); empty when it never engaged
//   zone                 the pass judge's zone when that decision was first taken, else the last
//                        zone it gave (e.g. pass_through_yellow)
//   emergency_stop       the decision was emergency_stop
//   stop_position_error  the recorded stop at this light: rest position - stop point
//
// Values are rounded to 1 mm; what does not apply is empty (std::nullopt).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "map/route_map.hpp"
#include "report/timeline.hpp"

namespace signalsim {

struct LightMetrics {
  std::string id;                          ///< tls id
  int link_index = -1;                     ///< the ego's link
  double stop_line_s = 0.0;                ///< route s of the stop line [m]
  bool reached = false;                    ///< the front crossed the stop line
  std::string state_at_line;               ///< link state (r, y, g, G, ...) as the front crossed; "" unknown
  std::optional<bool> red_light_violation; ///< crossed while the link showed r or u
  std::optional<double> stop_position_error;  ///< [m] rest position minus stop point; > 0 beyond it
  std::optional<std::string> decision;     ///< most restrictive judge decision: pass, stop, emergency_stop
  std::optional<std::string> zone;         ///< stoppable, optional_zone, dilemma_zone, pass_through_yellow, slow
  std::optional<bool> emergency_stop;      ///< the judge ordered an emergency stop here
};

/// One entry per signalised approach on the route, in route order. A run with a light log
/// (signalsim-driven) reads each light's own judge from it; otherwise the timeline rows that show
/// the light (SUMO driving, a timeline read back from files).
std::vector<LightMetrics> measure_lights(const RouteMap& route, const RunRecord& record);

}  // namespace signalsim
