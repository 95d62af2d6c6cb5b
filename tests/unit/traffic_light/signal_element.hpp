// A perceived signal element for the traffic-light unit tests: a colour, a shape (a circle unless
// given), a confidence (1 unless given) and a status (solid on unless given).
#pragma once

#include "traffic_light/signal_elements.hpp"

namespace signalsim::test {

inline SignalElement el(SignalColor c, SignalShape s = SignalShape::Circle, double conf = 1.0,
                        SignalStatus st = SignalStatus::SolidOn) {
  return SignalElement{c, s, st, conf};
}

}  // namespace signalsim::test
