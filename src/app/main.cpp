// signalsim command line. Each subcommand lives in its own file (see command.hpp).
#include <iostream>
#include <vector>

#include "app/command.hpp"
#include "app/html_report.hpp"
#include "scenario/data_dir.hpp"

namespace signalsim::app {

std::string single_line(const std::string& message) {
  // SUMO's messages may span lines ("...\n In file 'x'\n At line/column 2/1."): one line, blanks joined.
  std::string out;
  bool blank = false;
  for (const char c : message) {
    if (c == '\n' || c == '\r' || c == '\t' || c == ' ') {
      blank = true;
      continue;
    }
    if (blank && !out.empty()) out += ' ';
    blank = false;
    out += c;
  }
  return out;
}

int report_bad_input(const std::string& message) {
  std::cerr << "signalsim: " << single_line(message) << "\n";
  return kExitBadInput;
}

int report_interrupted(const std::string& message) {
  std::cerr << "signalsim: " << single_line(message) << "\n";
  return kExitInterrupted;
}

}  // namespace signalsim::app

int main(int argc, char** argv) {
  using namespace signalsim::app;
  using signalsim::kExitBadInput;
  remember_command_line(argc, argv);  // OUT/command.json of the batch commands
  CLI::App app{"signalsim: Autoware's turn-signal decider and traffic-light judge on SUMO"};
  app.set_version_flag("--version", kVersionText);
  app.require_subcommand(1);
  const std::vector<Command> commands = {add_run_command(app), add_inspect_command(app),
                                         add_countries_command(app),
                                         add_batch_command(app), add_sweep_command(app), add_check_command(app),
                                         add_compare_command(app), add_report_command(app), add_generate_command(app),
                                         add_schema_command(app),
                                         add_run_chunk_command(app),
                                         add_worker_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return report_bad_input(std::string(e.what()) + " (see 'signalsim --help')");
  }
  // The data (presets, signalsim-plot) is looked for once, before any command: a broken installation is
  // one line and exit 2, not a failure in the middle of a batch.
  if (const signalsim::DataDirLookup& data = signalsim::find_data_dir(); data.path.empty())
    return report_bad_input(data.where + ": " + data.reason);
  for (const Command& command : commands)
    if (command.sub->parsed()) return command.run();
  return kExitBadInput;
}
