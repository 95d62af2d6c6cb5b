// The run record's small conversions: the driver's name.
#include "report/timeline.hpp"

namespace signalsim {

std::string_view to_string(Driver driver) { return driver == Driver::Sumo ? "sumo" : "signalsim"; }

}  // namespace signalsim
