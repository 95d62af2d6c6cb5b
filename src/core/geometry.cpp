#include "core/geometry.hpp"

namespace signalsim {

double normalize_angle(double radians) {
  double wrapped = std::remainder(radians, 2.0 * std::numbers::pi);
  if (wrapped <= -std::numbers::pi) wrapped += 2.0 * std::numbers::pi;
  return wrapped;
}

}  // namespace signalsim
