// The two ports between a run's core and its SUMO session (docs/architecture.md "The step as a
// system"): observe reads exactly what the core demanded, at the step's start; apply is the only
// writer, then advances SUMO one step. The order of the calls within apply is part of the behaviour
// (SUMO's results can depend on it): keep it.
#pragma once

#include "session/sumo_session.hpp"
#include "step/step_ports.hpp"

namespace signalsim {

/// The step's observation: `ego` (read first, to locate the front) and what `want` asks for. Throws
/// sumo::SumoError when SUMO fails.
StepObservation observe(const sumo::SumoSession& session, sumo::EgoState ego, const ObservationDemand& want);

/// Sends `commands` (nothing when `commands.drive` is false), advances SUMO one step and reads what
/// it says back. Throws sumo::SumoError when SUMO fails.
StepFeedback apply(sumo::SumoSession& session, const Commands& commands);

}  // namespace signalsim
