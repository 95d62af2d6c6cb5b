// docs/behaviour.md §T4.3 FIRST_ACTIVE, shared by the intersection and roundabout queues.
#pragma once

#include <deque>

#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

/// The head of the queue while its required end (base_link-referenced) is not passed; the last
/// element is returned without an end check (docs/behaviour.md §T12.1.6). EMPTY for an empty queue.
TurnSignalInfo first_active(std::deque<TurnSignalInfo> queue, const EgoOnRoute& ego);

}  // namespace signalsim
