// Notes on stderr: facts about the input a user should know that are not errors (keys of an
// Autoware parameter file signalsim does not use, scenario keys that replace a vehicle_info value).
// Each note is printed once per process (a batch loads every scenario in the parent, its workers run
// quietly), and never when notes are turned off (`run --quiet`).
#pragma once

#include <string>

#include "scenario/parameters.hpp"

namespace signalsim {

/// Turns notes on (the default) or off for this process.
void set_notes_enabled(bool enabled);

/// Forgets which notes were printed: a batch's persistent worker starts each run as a fresh process
/// would (app/worker_command.cpp).
void forget_printed_notes();

/// Prints "signalsim: note: <text>" on stderr unless a note with the same text was printed before.
void note_once(const std::string& text);

/// The note's text (for tests): "<file>: N keys signalsim does not use: a, b, ... (+M more; all in
/// summary.json parameter_files)".
std::string unused_parameters_note(const UnusedParameters& unused);

}  // namespace signalsim
