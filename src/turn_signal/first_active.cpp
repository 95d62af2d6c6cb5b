// FIRST_ACTIVE over a request queue (see the header).
#include "turn_signal/first_active.hpp"

namespace signalsim {

TurnSignalInfo first_active(std::span<const TurnSignalInfo> queue, const EgoOnRoute& ego) {
  for (std::size_t i = 0; i < queue.size(); ++i) {
    if (i + 1 == queue.size()) return queue[i];
    if (queue[i].required_end - ego.s_base >= 0.0) return queue[i];
  }
  return {};
}

}  // namespace signalsim
