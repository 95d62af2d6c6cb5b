// The run record's small conversions: a blinker as SUMO's signal bits, the driver's name.
#include "report/timeline.hpp"

namespace signalsim {

int signal_mask(Blinker b) {
  switch (b) {
    case Blinker::Left: return sumo::kBlinkerLeft;
    case Blinker::Right: return sumo::kBlinkerRight;
    case Blinker::Hazard: return sumo::kBlinkerEmergency;
    case Blinker::None: break;
  }
  return 0;
}

std::string_view to_string(Driver driver) { return driver == Driver::Sumo ? "sumo" : "signalsim"; }

}  // namespace signalsim
