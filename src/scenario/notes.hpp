// Notes and warnings on stderr: facts about the input a user should know that are not errors (keys of
// an Autoware parameter file signalsim does not use, scenario keys that replace a vehicle_info value),
// and input that may not do what its author meant (a key Autoware dropped, a country preset for the
// other driving side). Each is printed once per process (a batch loads every scenario in the parent,
// its workers run quietly), and never when notes are turned off (`--quiet`; summary.json keeps the
// warnings).
#pragma once

#include <string>

#include "scenario/parameters.hpp"

namespace signalsim {

/// Turns notes and warnings on (the default) or off for this process.
void set_notes_enabled(bool enabled);

/// Forgets which notes were printed, and any held back: a batch's persistent worker starts each run as
/// a fresh process would (app/worker_command.cpp).
void forget_printed_notes();

/// Holds notes and warnings back, in the order they come, until release_notes(): a command that checks
/// all its input before it runs anything (batch, sweep, check, compare) prints them only once the
/// input is good, so that bad input stays one line.
void hold_notes();

/// Prints the notes and warnings held back and stops holding them.
void release_notes();

/// Prints "signalsim: note: <text>" on stderr unless a note with the same text was printed before.
void note_once(const std::string& text);

/// Prints "signalsim: warning: <text>" on stderr unless a warning with the same text was printed before.
void warn_once(const std::string& text);

/// The note's text (for tests): "<file>: N keys signalsim does not use: a, b, ... (+M more; all in
/// summary.json parameter_files)".
std::string unused_parameters_note(const UnusedParameters& unused);

}  // namespace signalsim
