// Which implementation decides a role of a run (docs/decider.md "Naming the system under test"): the
// scenario keys `decider:` and `light_judge:` (and --decider / --light-judge, which set them) name
// signalsim's own module ("reference", the default), a C ABI plugin (lib:PATH), a JSON-lines process
// (exec:COMMAND), another TraCI client (traci) or the bundled autoware_core decider.
#pragma once

#include <string>

namespace signalsim {

struct SutSpec {
  enum class Kind { Reference, Library, Exec, Traci, AutowareCore };
  Kind kind = Kind::Reference;
  std::string text = "reference";  ///< as written (summaries, messages)
  std::string target;              ///< lib: the library's path (resolved); exec: the command as written
  std::string base_dir;            ///< the directory of the file that named it: exec's working directory
  bool operator==(const SutSpec&) const = default;
};

/// Parses "reference", "lib:PATH", "exec:COMMAND", "traci" or "autoware_core" (a lib: path relative to
/// `base_dir`). Returns the reason when the text is none of them (or lib:/exec: is empty), else "".
std::string parse_sut_spec(const std::string& text, const std::string& base_dir, SutSpec& out);

/// The override item that names a SUT for `key` ("decider" or "light_judge") relative to `base_dir`
/// instead of the scenario file's directory: `key={sut: "TEXT", dir: "ABSOLUTE_DIR"}` (the command
/// line's --decider gives the current directory, a sweep file its own). The scenario reader takes this
/// mapping in place of the plain text; `text` stays as given (summaries, results.csv).
std::string sut_override(const std::string& key, const std::string& text, const std::string& base_dir);

}  // namespace signalsim
