// One subcommand of the command line: its CLI11 sub-app and the function that runs it.
// Exit codes for every command: 0 success, 1 an expectation (or regression) failed, 2 bad input;
// sweep --plot and compare: 3 the picture failed; batch, sweep and check: 4 a run errored (no verdict);
// 130 interrupted, `run`: 143 on SIGTERM (see README).
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace signalsim::app {

inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitPicture = 3;        ///< sweep --plot, compare: the runs were fine, the picture failed
inline constexpr int kExitRunErrors = 4;      ///< batch, sweep, check: a run errored (no verdict; wins over 1)
inline constexpr int kExitInterrupted = 130;  ///< SIGINT (batch, sweep, check, compare: also SIGTERM)
inline constexpr int kExitTerminated = 143;   ///< `run` stopped by SIGTERM (128 + 15)

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

/// `message` on one line: every run of blanks and line breaks becomes one space.
std::string single_line(const std::string& message);
/// Prints "signalsim: <message>" (on one line) to stderr and returns kExitBadInput.
int report_bad_input(const std::string& message);

Command add_run_command(CLI::App& app);
Command add_inspect_command(CLI::App& app);
Command add_countries_command(CLI::App& app);
Command add_batch_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_generate_command(CLI::App& app);
Command add_compare_command(CLI::App& app);

}  // namespace signalsim::app
