// One subcommand of the command line: its CLI11 sub-app and the function that runs it (exit codes:
// report/exit_codes.hpp).
#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "report/exit_codes.hpp"

namespace signalsim::app {

/// What `signalsim --version` prints; OUT/command.json's `version`.
inline constexpr const char* kVersionText = "signalsim 0.1.0";

struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

/// `message` on one line: every run of blanks and line breaks becomes one space.
std::string single_line(const std::string& message);
/// Prints "signalsim: <message>" (on one line) to stderr and returns kExitBadInput.
int report_bad_input(const std::string& message);
/// Prints "signalsim: <message>" (on one line) to stderr and returns kExitInterrupted: a batch
/// command stopped by SIGINT or SIGTERM before its runs started (batch/interrupt_guard.hpp).
int report_interrupted(const std::string& message);

Command add_run_command(CLI::App& app);
Command add_inspect_command(CLI::App& app);
Command add_countries_command(CLI::App& app);
Command add_batch_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_generate_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_schema_command(CLI::App& app);
Command add_run_chunk_command(CLI::App& app);
Command add_worker_command(CLI::App& app);
Command add_report_command(CLI::App& app);

}  // namespace signalsim::app
