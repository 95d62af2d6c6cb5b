// docs/behaviour.md §T4.3 FIRST_ACTIVE, shared by the intersection and roundabout queues.
#pragma once

#include <span>

#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

/// The head of the queue while its required end (base_link-referenced) is not passed; the last
/// element is returned without an end check (docs/behaviour.md §T12.1.6). EMPTY for an empty queue.
/// The reference pops a std::queue; walking a span gives the same element without allocating.
TurnSignalInfo first_active(std::span<const TurnSignalInfo> queue, const EgoOnRoute& ego);

}  // namespace signalsim
