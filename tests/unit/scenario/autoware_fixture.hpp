// The path of a test fixture that mimics one of Autoware's parameter files (tests/data/autoware/).
#pragma once

#include <string>

namespace signalsim::test {

inline std::string fixture(const std::string& name) {
  return std::string(SIGNALSIM_SOURCE_DIR) + "/tests/data/autoware/" + name;
}

}  // namespace signalsim::test
