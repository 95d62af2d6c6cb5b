#include "turn_signal/first_active.hpp"

namespace signalsim {

TurnSignalInfo first_active(std::deque<TurnSignalInfo> queue, const EgoOnRoute& ego) {
  while (!queue.empty()) {
    if (queue.size() == 1) return queue.front();
    if (queue.front().required_end - ego.s_base >= 0.0) return queue.front();
    queue.pop_front();
  }
  return {};
}

}  // namespace signalsim
