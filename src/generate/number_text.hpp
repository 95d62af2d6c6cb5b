// Numbers as the generator writes them: fixed decimals, never "-0.0", locale-independent.
#pragma once

#include <string>

namespace signalsim::generate {

/// `v` with `decimals` digits after the point ("28.9", "0.30"); -0 is written as 0.
std::string fixed(double v, int decimals = 1);

}  // namespace signalsim::generate
