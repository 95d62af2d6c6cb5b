// Fixed-decimal numbers for the generated files.
#include "generate/number_text.hpp"

#include <cmath>
#include <cstdio>

namespace signalsim::generate {

std::string fixed(double v, int decimals) {
  const double scale = std::pow(10.0, decimals);
  double r = std::round(v * scale) / scale;
  if (r == 0.0) r = 0.0;  // no "-0"
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, r);
  return buffer;
}

}  // namespace signalsim::generate
