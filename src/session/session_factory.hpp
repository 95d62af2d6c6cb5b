// The back-ends' factories, one per translation unit (libsumo and libtraci cannot share one, docs/behaviour.md
// §S1); open_session (session_factory.cpp) picks one. Private to src/session.
#pragma once

#include <memory>

#include "session/sumo_session.hpp"

namespace signalsim::sumo {

std::unique_ptr<SumoSession> open_embedded_session(const SessionConfig& config);
/// net_load_error on libsumo.
std::string embedded_net_load_error(const std::string& net_path);
/// gui (starts sumo-gui itself) and connect (an existing server).
std::unique_ptr<SumoSession> open_traci_session(const SessionConfig& config);

}  // namespace signalsim::sumo
