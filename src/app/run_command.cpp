// `signalsim run SCENARIO --out DIR`: one scenario, one SUMO, the three output files.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "app/cli_numbers.hpp"
#include "app/command.hpp"
#include "app/override_flags.hpp"
#include "app/sut_flags.hpp"
#include "app/plot_tool.hpp"
#include "report/expectations.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"
#include "report/outputs.hpp"
#include "step/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "scenario/sumo_inputs.hpp"
#include "sim/egoless_run.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"
#include "session/interruption.hpp"
#include "net/sumo_log.hpp"
#include "report/run_files.hpp"
#include "report/summary_sections.hpp"
#include "session/sumo_session.hpp"
#include "sim/session_setup.hpp"
#include "sut/sut_factory.hpp"

namespace signalsim::app {
namespace {


// sumo-gui's zoom in fleet mode [%]: about 400 m across, the traffic around the ego (docs/fleet.md).
constexpr double kFleetGuiZoom = 200.0;

// How an embedded SUMO's failed start begins its message (session_embedded.cpp).
constexpr const char* kSumoLoadFailure = "SUMO could not load the simulation: ";

struct RunOptions {
  std::string scenario_path;
  std::string out_dir = "out";
  ScenarioOverrides overrides;
  bool gui = false;            ///< run in sumo-gui (libtraci)
  int gui_delay_ms = -1;       ///< -1: not given
  std::string connect;         ///< HOST:PORT of a SUMO someone else started
  bool connect_given = false;  ///< --connect was given (also as "", which is refused)
  int client_order = -1;       ///< -1: not given
  double traci_timeout = -1.0;  ///< [s]; -1: not given
  bool quiet = false;
  bool plot = false;  ///< draw the run's pictures with signalsim-plot afterwards
  std::string driver = "signalsim";  ///< who drives the ego: signalsim, or sumo (observed only)
  SutFlags suts;                     ///< --decider / --light-judge as given (they are overrides too)
  bool fleet = false;                ///< --fleet: fleet mode on (docs/fleet.md)
};

// Every exit-2 path: the output directory must not keep a previous run's files that could pass for
// this run's, so they are replaced by a summary with status "error" and the message. A run a signal
// stopped (whatever exception the unwinding raised: a TraCI call cut short by EINTR, ...) says
// "interrupted" instead and exits 128 + the signal: 130 for SIGINT, 143 for SIGTERM.
int fail(const RunOptions& options, const std::optional<Scenario>& scenario, const std::string& message) {
  const int signal = sumo::interruption_signal();
  const std::string text = single_line(signal ? options.scenario_path + ": " + sumo::Interrupted(signal).what() : message);
  try {
    write_error_summary(options.out_dir, scenario ? &*scenario : nullptr, text, signal ? "interrupted" : "error");
  } catch (const std::exception&) {  // an unwritable directory: the message below is what matters
  }
  report_bad_input(text);
  return signal ? 128 + signal : kExitBadInput;
}

// The back-end from --gui / --connect (at most one).
RunContext run_context(const RunOptions& options) {
  RunContext context;
  context.out_dir = options.out_dir;
  context.sumo_drives = options.driver == "sumo";
  if (options.gui && options.connect_given)
    throw InputError("--gui", 0, "--gui and --connect exclude each other (attach sumo-gui with --connect instead)");
  if (!options.gui && options.gui_delay_ms >= 0) throw InputError("--gui-delay", 0, "only applies with --gui");
  if (!options.connect_given && options.client_order >= 0)
    throw InputError("--client-order", 0, "only applies with --connect");
  if (!options.connect_given && !options.gui && options.traci_timeout >= 0)
    throw InputError("--traci-timeout", 0, "only applies with --connect or --gui");
  if (options.gui) {
    context.backend.kind = sumo::BackendKind::Gui;
    context.backend.gui_delay_ms = std::max(0, options.gui_delay_ms);
    context.backend.screenshot = (std::filesystem::path(options.out_dir) / run_files::kGuiScreenshot).string();
    context.backend.traci_timeout = std::max(0.0, options.traci_timeout);  // none unless given: a user may pause it
  } else if (options.connect_given) {
    const auto colon = options.connect.rfind(':');
    const std::string digits = colon == std::string::npos ? std::string() : options.connect.substr(colon + 1);
    const bool all_digits = !digits.empty() && digits.size() <= 5 &&
                            std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); });
    const int port = all_digits ? std::stoi(digits) : 0;
    const bool parsed = colon > 0 && all_digits && port > 0 && port < 65536;
    if (!parsed) throw InputError("--connect", 0, "'" + options.connect + "' is not HOST:PORT (e.g. 127.0.0.1:8813)");
    context.backend.kind = sumo::BackendKind::Connect;
    context.backend.host = options.connect.substr(0, colon);
    context.backend.port = port;
    context.backend.client_order = std::max(1, options.client_order);
    if (options.traci_timeout >= 0) context.backend.traci_timeout = options.traci_timeout;
  }
  return context;
}

// A scenario without an ego (docs/fleet.md "Without an ego"): fleet mode over SUMO's traffic alone, on
// the embedded back-end; no expectations (none can be given), so the status is no_expectations.
int run_egoless(const RunOptions& options, const Scenario& scenario, const RunContext& context) {
  if (context.sumo_drives) throw InputError("--driver", 0, "--driver sumo drives the ego, and the scenario has none");
  if (options.plot) throw InputError("--plot", 0, "the pictures are of the ego's run, and the scenario has no ego");
  if (context.backend.kind != sumo::BackendKind::Embedded)
    throw InputError(options.gui ? "--gui" : "--connect", 0,
                     "a scenario without an ego (fleet: without ego:) runs on the embedded back-end only");
  const std::shared_ptr<const sumo::NetIndex> net = sumo::NetIndex::load_shared(scenario.net);
  set_notes_enabled(!options.quiet);
  for (const std::string& note : scenario.notes) note_once(note);
  for (const std::string& warning : scenario.warnings) warn_once(warning);
  clear_run_outputs(options.out_dir);  // as a run with an ego: no earlier run's files stay
  sumo::throw_if_interrupted();
  const auto start = std::chrono::steady_clock::now();
  RunRecord record = signalsim::run_egoless(scenario, *net, context);
  if (!record.sumo.log.empty()) record.sumo.log_counts = sumo::count_sumo_log(record.sumo.log, sumo::kDefaultEgoId);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<LawVerdict> law;
  const RunStatus status = run_status({}, law);
  write_run_outputs(options.out_dir, scenario, sumo::RoutePlan{}, record, {}, status, &law);
  if (!options.quiet)
    std::printf("%s: %s (no ego; %lld steps to t=%.1f s, ended by %s, %.2f s wall)\n"
                "  fleet: %d vehicles followed, %d signalled, %zu blinker changes, %d left to SUMO\n",
                scenario.name.c_str(), std::string(to_string(status)).c_str(), record.egoless->steps,
                record.egoless->end_time, record.egoless->ended.c_str(), wall, record.fleet->totals.vehicles_followed,
                record.fleet->totals.vehicles_signalled, record.fleet->events.size(), record.fleet->totals.left_to_sumo);
  return 0;
}

int run(const RunOptions& options) {
  std::optional<Scenario> scenario;
  // Ctrl-C / SIGTERM unwind the run (sumo-gui stopped by its PID, an error summary written).
  sumo::install_interruption_handlers();
  // Notes only once the input is known to be good: bad input is one line.
  set_notes_enabled(false);
  try {
    scenario = load_scenario(options.scenario_path, options.overrides);
    RunContext context = run_context(options);
    if (scenario->fleet.enabled) context.backend.gui_zoom = kFleetGuiZoom;  // the traffic around the ego
    if (!scenario->has_ego) return run_egoless(options, *scenario, context);
    // SUMO driving leaves no decision to a system under test: refused rather than silently not run.
    if (context.sumo_drives)
      for (const SutSpec* sut : {&scenario->decider, &scenario->light_judge})
        if (sut->kind != SutSpec::Kind::Reference)
          throw InputError("--driver", 0,
                           "--driver sumo lets SUMO decide, so the " +
                               std::string(sut == &scenario->decider ? "decider" : "light_judge") + " under test '" +
                               sut->text + "' cannot be in the loop (drop --driver sumo, or use compare)");
    check_systems_under_test(*scenario);  // a library or command that cannot be used: bad input before SUMO starts
    // One index per net and process while the file is unchanged: a worker's later runs on the same
    // net skip the load (answers do not depend on what earlier runs looked up).
    const std::shared_ptr<const sumo::NetIndex> net_ptr = sumo::NetIndex::load_shared(scenario->net);
    const sumo::NetIndex& net = *net_ptr;
    PlannedRun planned = plan_run(*scenario, net);
    check_expectations_apply(planned.scenario, planned.plan.map);
    set_notes_enabled(!options.quiet);
    for (const std::string& note : scenario->notes) note_once(note);
    for (const std::string& warning : scenario->warnings) warn_once(warning);
    // SUMO writes into the run directory while it runs: a previous run's files must go first, so
    // that an interrupted or failed run never leaves them looking like this one's.
    clear_run_outputs(options.out_dir);
    sumo::throw_if_interrupted();  // a signal while loading: stop before SUMO starts

    const auto start = std::chrono::steady_clock::now();
    RunRecord record;
    sumo::RoutePlan plan;
    std::optional<sumo::GuiPicture> picture;  // --gui: what gui.png shows
    {
      StartedRun started = start_run(std::move(planned), net, context);
      record = drive(started, net);
      picture = started.session->gui_picture();
      scenario = started.scenario;  // as run: a taken-over vehicle's values
      plan = std::move(started.plan);
    }  // SUMO closes here: its log is complete
    if (!record.sumo.log.empty())
      record.sumo.log_counts =
          sumo::count_sumo_log(record.sumo.log, scenario->ego.id.empty() ? sumo::kDefaultEgoId : scenario->ego.id);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto results = evaluate_expectations(*scenario, plan.map, record);
    const std::vector<LawVerdict> law = law_verdicts(*scenario, plan.map, record);
    const RunStatus status = run_status(results, law);
    write_run_outputs(options.out_dir, *scenario, plan, record, results, status, &law);
    if (!options.quiet) {
      std::printf("%s%s: %s (%zu steps, %.1f s simulated, %zu events, %.2f s wall)\n", scenario->name.c_str(),
                  context.sumo_drives ? " (driven by SUMO)" : "", std::string(to_string(status)).c_str(), record.rows.size(),
                  simulated_span(record, scenario->sumo.begin), record.events.size(), wall);
      if (record.fleet)
        std::printf("  fleet: %d vehicles followed, %d signalled, %zu blinker changes, %d left to SUMO\n",
                    record.fleet->totals.vehicles_followed, record.fleet->totals.vehicles_signalled,
                    record.fleet->events.size(), record.fleet->totals.left_to_sumo);
      for (const auto& r : results)
        std::printf("  [%s] %s: %s\n", r.passed ? "ok" : "FAIL", r.description.c_str(), r.detail.c_str());
      for (const LawVerdict& v : law)
        if (!v.passed)
          std::printf("  [FAIL] law: %s %s %s: %s\n", v.section.c_str(), v.id.c_str(), v.rule.c_str(), v.detail.c_str());
      if (status == RunStatus::NoExpectations)
        std::printf("  the scenario has no expectations (expect:): nothing was checked\n");
    }
    if (picture) caption_gui_picture(options.out_dir, *picture);  // a failed caption is reported, as a plot
    if (options.plot) run_plot_tool({options.out_dir});  // a failed plot is reported, the run's verdict stands
    return status == RunStatus::Failed ? kExitFailed : 0;
  } catch (const InputError& e) {
    return fail(options, scenario, e.what());
  } catch (const sumo::NetError& e) {
    return fail(options, scenario, e.what());
  } catch (const sumo::SumoError& e) {
    // A SUMO that did not start because of an option the scenario passed on: that option's line.
    const std::string message = e.what();
    if (scenario && message.rfind(kSumoLoadFailure, 0) == 0)
      if (const std::optional<InputError> at = sumo_option_error(*scenario, message)) return fail(options, scenario, at->what());
    return fail(options, scenario, options.scenario_path + ": " + message);
  } catch (const std::exception& e) {
    return fail(options, scenario, options.scenario_path + ": " + e.what());
  }
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand("run", "Run one scenario and write timeline.csv, events.csv, summary.json");
  sub->add_option("scenario", options->scenario_path, "Scenario YAML file")->required();
  sub->add_option("--out", options->out_dir, "Output directory (created)")->capture_default_str();
  add_override_flags(sub, options->overrides.set,
                     "Override: a scenario key (seed=3, ego.max_speed=10, country=de) or a parameter "
                     "(turn_signal_search_time=2.5); repeatable");
  sub->add_flag("--quiet", options->quiet, "Print nothing on success");
  add_sut_flags(sub, options->overrides.set, options->suts);
  sub->add_flag("--plot", options->plot, "Draw PNGs of the run into OUT/plots with signalsim-plot");
  sub->add_option("--driver", options->driver,
                  "Who drives the ego: signalsim (its decider, judge and planners) or sumo (SUMO's own blinker, "
                  "lights and lane changes, observed only)")
      ->check(CLI::IsMember({"signalsim", "sumo"}))
      ->capture_default_str();
  sub->add_flag("--gui", options->gui,
                "Run in sumo-gui (needs a display): the ego tracked in the view, a screenshot in OUT/gui.png");
  sub->add_option("--gui-delay", options->gui_delay_ms, "With --gui: sumo-gui's delay between steps [ms]")
      ->check(CLI::Range(0, 10000));
  sub->add_option("--connect", options->connect,
                  "Attach to a SUMO started with --remote-port (HOST:PORT); step in lock-step with its other clients")
      ->each([options](const std::string&) { options->connect_given = true; });
  sub->add_option("--client-order", options->client_order, "With --connect: this client's TraCI order (setOrder)")
      ->check(CLI::Range(1, 1000));
  sub->add_option("--traci-timeout", options->traci_timeout,
                  "With --connect or --gui: the longest wait in seconds for SUMO to accept the connection and to "
                  "answer each request, else the run ends with an error (default 30 with --connect, none with --gui)")
      ->check(number_between(0.1, 86400.0));
  sub->add_flag("--fleet", options->fleet,
                "Fleet mode: every vehicle of SUMO's traffic gets its blinker from the reference decider (the "
                "scenario's fleet: filters kept; the same as --set fleet.signals=set, which a --set fleet.signals "
                "given beside it overrides, docs/fleet.md)");
  return {sub, [options] {
            // A --set fleet.signals=... beside --fleet (observe) is the user's word and wins.
            const bool signals_set = std::any_of(options->overrides.set.begin(), options->overrides.set.end(),
                                                 [](const std::string& item) { return item.starts_with("fleet.signals="); });
            if (options->fleet && !signals_set) options->overrides.set.push_back("fleet.signals=set");
            return run(*options);
          }};
}

}  // namespace signalsim::app
