// Plain files a user can open: timeline.csv, events.csv, summary.json.
// Each file is written to "<name>.tmp" and renamed, and summary.json comes last: a directory with a
// summary.json whose status is not "error" holds a complete run.
#pragma once

#include <string>
#include <vector>

#include "core/number_text.hpp"  // fixed(): numbers as the files write them
#include "scenario/scenario.hpp"
#include "report/law_verdicts.hpp"
#include "report/timeline.hpp"
#include "route/route_builder.hpp"

namespace signalsim {

/// Outcome of a run as the summary and the exit code see it: "passed" (every expectation held),
/// "failed" (one did not; exit code 1), "no_expectations" (the scenario has none, so nothing was
/// checked; exit code 0, not a failure), "error" (exit code 2).
enum class RunStatus { Passed, Failed, NoExpectations, Error };
std::string_view to_string(RunStatus status);

/// The status of a finished run from its expectation results: NoExpectations when there are none.
RunStatus run_status(const std::vector<ExpectationResult>& results);
/// The same with the law's verdicts (law_verdicts.hpp): a failed verdict fails the run too.
RunStatus run_status(const std::vector<ExpectationResult>& results, const std::vector<LawVerdict>& law);

/// `v2i_column`: append the column v2i_time_to_red (only for a run with V2I on, so that every other
/// run's file stays as it was).
/// The timeline's optional columns, after the fixed ones in this order (docs/outputs.md).
struct TimelineColumns {
  bool v2i = false;          ///< v2i_time_to_red (V2I runs)
  bool decider = false;      ///< ref_blinker, ref_blinker_source (a decider under test)
  bool light_judge = false;  ///< ref_tl_decision, tl_reason (a light judge under test)
};
void write_timeline_csv(const std::string& path, const std::vector<TimelineRow>& rows, TimelineColumns columns = {});
void write_events_csv(const std::string& path, const std::vector<TimelineEvent>& events);

/// Writes timeline.csv, events.csv and summary.json into `dir` (created if missing). `law`: the
/// run's law verdicts (law_verdicts.hpp); nullptr: computed here.
void write_run_outputs(const std::string& dir, const Scenario& scenario, const sumo::RoutePlan& plan,
                       const RunRecord& record, const std::vector<ExpectationResult>& results,
                       RunStatus status, const std::vector<LawVerdict>* law = nullptr);

/// Creates `dir` and removes the files of an earlier run there (summary.json first, then the timeline,
/// the events and the gui screenshot), before SUMO starts writing into it.
void clear_run_outputs(const std::string& dir);

/// Removes an earlier run's files and writes only summary.json, status "error" (or "interrupted": a
/// signal stopped the run), with the message (a run that could not finish).
void write_error_summary(const std::string& dir, const Scenario* scenario, const std::string& message,
                         const std::string& status = "error");

}  // namespace signalsim
