// One subcommand of the command line: its CLI11 sub-app and the function that runs it.
// Exit codes for every command: 0 success, 1 an expectation (or regression) failed, 2 bad input.
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace signalsim::app {

inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitInterrupted = 130;  ///< SIGINT / SIGTERM

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

/// Prints "signalsim: <message>" to stderr and returns kExitBadInput.
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
