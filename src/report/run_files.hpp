// The files of a run directory and of a batch's output directory: the one home of their names
// (docs/outputs.md). The report writes the run's files, the session set-up points SUMO's log there,
// `run --gui` saves its screenshot there, and batch, check and compare read them back.
#pragma once

#include <array>

namespace signalsim::run_files {

inline constexpr const char* kTimeline = "timeline.csv";     ///< a row per step
inline constexpr const char* kEvents = "events.csv";         ///< a row per change
inline constexpr const char* kSummary = "summary.json";      ///< the run's verdict, metrics, settings
inline constexpr const char* kGuiScreenshot = "gui.png";     ///< `run --gui`: the view at the first blinker
inline constexpr const char* kFleetEvents = "fleet_events.csv";  ///< fleet mode: a row per blinker change
inline constexpr const char* kSumoLog = "sumo.log";          ///< SUMO's messages
inline constexpr const char* kMetrics = "metrics.json";      ///< batch's metrics of a summary without them
inline constexpr const char* kJudgeCurves = "judge_curves.csv";  ///< the light judge's curves over the speed
/// What a run writes anew: removed before a run writes its files or an error summary, so that no
/// stale file describes another run.
inline constexpr std::array<const char*, 6> kRunOutputs = {kSummary, kTimeline, kEvents, kJudgeCurves, kGuiScreenshot,
                                                          kFleetEvents};

inline constexpr const char* kResults = "results.csv";       ///< a batch's table, a row per run
inline constexpr const char* kRunsDir = "runs";              ///< a batch's run directories

}  // namespace signalsim::run_files
