// SUMO's own options as a user passes them (scenario `sumo_args`, the options of a `.sumocfg`): which
// ones signalsim owns (refused, with the reason), which name an output file (a relative path lands in
// the run's output directory) or an input file (a relative path is resolved from the file that names
// it). The tables are SUMO 1.15's FILE options (`sumo --save-template`; a test checks them against the
// installed SUMO). Pure functions: no SUMO.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace signalsim::sumo {

/// A refused or malformed option. what() says which and why.
class SumoOptionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class OptionKind {
  Owned,       ///< signalsim sets it (net, step length, seed, TraCI port, its log, ...)
  OutputFile,  ///< names a file SUMO writes
  InputFile,   ///< names a file SUMO reads
  Other,       ///< anything else: passed on as it is
};

/// The long name of an option given by any of SUMO's names for it ("tripinfo" -> "tripinfo-output",
/// "c" -> "configuration-file"); other names unchanged.
std::string canonical_option(const std::string& name);

/// What `name` (a long name, without dashes) is. For Owned, `reason` says why it is refused.
OptionKind option_kind(const std::string& name, std::string* reason = nullptr);

/// Every FILE option of SUMO 1.15 this file classifies (for the test against `sumo --save-template`).
std::vector<std::string> classified_file_options();

/// One option as given: its canonical name and its value (empty for a bare boolean switch).
struct SumoOption {
  std::string name;
  std::string value;
  bool has_value = false;
};

/// Splits command-line tokens ("--fcd-output", "fcd.xml", "--fcd-output.signals", "true", "-v",
/// "--end=10") into options. A token that starts with '-' followed by a letter is an option name
/// (`--name=value` carries its value); the next token is its value unless it is an option name
/// itself (so "-1" is a value). Throws SumoOptionError for a value without an option.
std::vector<SumoOption> parse_sumo_tokens(const std::vector<std::string>& tokens);

/// The options as SUMO command-line tokens, after the checks and path rules above: an Owned option
/// throws SumoOptionError naming it and the reason (`source` says where it came from, e.g.
/// "sumo_args"); a relative output path is made relative to `out_dir`, a relative input path to
/// `input_dir`. Options of SUMO's gui_only category are dropped unless `gui`.
std::vector<std::string> sumo_tokens(const std::vector<SumoOption>& options, const std::string& source,
                                     const std::string& out_dir, const std::string& input_dir, bool gui);

/// Whether `name` is an option of sumo-gui only (gui-settings-file, ...).
bool gui_only_option(const std::string& name);

}  // namespace signalsim::sumo
