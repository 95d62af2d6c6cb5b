// The traffic-light stage of the step loop. Every light on the route whose stop line lies within
// the horizon ahead (down to 2 m behind the front) has its own judge and its own perception model
// (docs/behaviour.md §L1.1: one scene module per light on the path); a light is dropped once the front is
// more than 2 m past its stop line (the judge's GO_OUT dead line, docs/behaviour.md §L1.2), whatever its state.
// With V2I on (docs/behaviour.md §L1.7) each light also has its own V2I channel: its programs are asked for
// once, when the light is first judged, its timing every step, and the predicted phases, as signal
// elements of the ego's approach, reach its judge through the channel's faults. The stage reads no
// SUMO: it says what it needs (demand) and is handed the step's observation.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "route/approach_lights.hpp"
#include "session/signal_timing.hpp"
#include "step/step_ports.hpp"
#include "traffic_light/perception_model.hpp"
#include "traffic_light/traffic_light_judge.hpp"
#include "traffic_light/v2i_channel.hpp"

namespace signalsim {

/// LightStep::observed (the timeline's tl_observed) of a message delivered without the light
/// (docs/behaviour.md §L1.3).
inline constexpr const char* kMissingFromMessage = "missing";

/// One light in one step.
struct LightStep {
  const sumo::ApproachLight* light = nullptr;
  char own_state = 0;                 ///< true state of the ego's link
  bool judged = false;                ///< the judge ran (the light regulates the ego's link)
  /// What perception delivered this step: "" nothing, kMissingFromMessage a message without this light.
  std::string observed;
  double front_to_stop_line = 0.0;    ///< [m]
  TrafficLightJudgeResult result;     ///< with a light judge under test: its decision and stop point
  /// What perception delivered this step, kept for a light judge under test (keep_delivered).
  bool delivered = false;
  std::vector<SignalElement> elements;
  /// With a light judge under test: the reference judge's decision (run in shadow) and the SUT's reason.
  std::optional<JudgeDecision> reference_decision;
  std::string sut_reason;
};

/// The V2I predictions of one light as signal elements of this approach (docs/behaviour.md §L1.7, §S3):
/// the program's predicted phases (signal_timing.hpp) from `timing`, each turned into what the ego's
/// approach shows (phases where the ego's link is off are left out). Empty when the running program
/// is not among `programs` or its phase is out of range (e.g. a state set by TraCI). Never throws.
std::vector<SignalPrediction> v2i_predictions(const std::vector<sumo::LightProgram>& programs,
                                              const sumo::LightTiming& timing, const sumo::ApproachLight& light);

class TrafficLightStage {
 public:
  /// `v2i`: the channels' faults and seed (each light's channel is seeded apart), used only with
  /// judge.v2i.use_remaining_time.
  TrafficLightStage(std::vector<sumo::ApproachLight> lights, const TrafficLightJudgeParameters& judge,
                    const PerceptionModelParameters& perception, double horizon, V2iChannelParameters v2i = {});

  /// What a step at `s_front` reads of the lights: the state of every light in the window (with V2I
  /// its timing, and its programs until it has them), else the state of the next light beyond it.
  void demand(double s_front, ObservationDemand& want) const;

  /// One step for every light in the window, nearest first (empty when none). `seen` holds the
  /// readings demand() asked for at this `s_front`.
  std::vector<LightStep> step(double now, double s_front, double speed, double accel, const StepObservation& seen);

  /// The next light ahead that is not yet dropped (for the timeline when none is in the window).
  const sumo::ApproachLight* next_light() const;

  /// Keeps each step's delivered signal elements in LightStep (a light judge under test reads them).
  void keep_delivered() { keep_delivered_ = true; }

 private:
  struct Tracked {
    Tracked(sumo::ApproachLight approach, PerceptionModel model)
        : light(std::move(approach)), perception(std::move(model)) {}
    sumo::ApproachLight light;
    PerceptionModel perception;
    std::optional<TrafficLightJudge> judge;
    bool dropped = false;
    std::optional<V2iChannel> v2i;                ///< with V2I on
    std::optional<std::vector<sumo::LightProgram>> programs;  ///< read when first judged (V2I)
    // What the last state showed the ego, and the text of the last observation: a light's state
    // changes a few times a cycle, so most steps reuse them.
    bool truth_known = false;
    std::string truth_state;
    std::optional<std::vector<SignalElement>> truth;
    bool described = false;
    std::vector<SignalElement> described_elements;
    std::string described_text;

    const std::optional<std::vector<SignalElement>>& truth_of(const std::string& state);
    const std::string& describe(const std::vector<SignalElement>& elements);
  };
  std::vector<Tracked> lights_;
  std::size_t first_ = 0;  // lights before this one are all dropped
  TrafficLightJudgeParameters judge_params_;
  double horizon_;
  V2iChannelParameters v2i_;
  bool keep_delivered_ = false;
};

/// [m] SUMO's own stop for a red link (jmStoplineGap, 1 m before the line, at its type's decel) binds
/// over the judge's jerk-limited stop only in the last metre or two; this far from the line the
/// judge's stop takes SUMO's right of way off whatever lanes lie between.
inline constexpr double kStoplineGapReach = 5.0;

/// Whether the light's judge alone decides the next junction the ego enters, its link showing r, u,
/// y or Y: the ego is on a normal lanelet that is the approach of a light in `lights` (no other
/// junction lies between), or a stop is requested for a light whose line is within
/// kStoplineGapReach of the front (a stub approach behind a tiny junction). Then SUMO's right of way
/// must not apply (docs/behaviour.md §S4: it would hold a slow ego 1 m before the red line on its
/// own); the judge decides.
bool light_decides_next_junction(const RouteMap& route, double s_front, const std::vector<LightStep>& lights);

}  // namespace signalsim
