// Look-ups on the step's ports (step_ports.hpp).
#include "step/step_ports.hpp"

namespace signalsim {

LightDemand& ObservationDemand::light(const std::string& tls_id) {
  for (LightDemand& l : lights)
    if (l.tls_id == tls_id) return l;
  lights.push_back({tls_id});
  return lights.back();
}

const LightReading* StepObservation::light(const std::string& tls_id) const {
  for (const LightReading& l : lights)
    if (l.tls_id == tls_id) return &l;
  return nullptr;
}

}  // namespace signalsim
