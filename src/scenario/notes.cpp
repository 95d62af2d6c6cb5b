// Once-per-process notes and warnings on stderr.
#include "scenario/notes.hpp"

#include <iostream>
#include <mutex>
#include <set>
#include <vector>

namespace signalsim {
namespace {

constexpr std::size_t kNamesShown = 6;  // the rest are counted; summary.json lists all

struct NoteState {
  std::mutex mutex;
  bool enabled = true;
  bool holding = false;
  std::set<std::string> printed;
  std::vector<std::string> held;  ///< whole lines, while holding
};

NoteState& state() {
  static NoteState s;
  return s;
}

// "signalsim: <kind>: <text>" once per process (a note and a warning of one text are apart).
void print_once(const char* kind, const std::string& text) {
  NoteState& s = state();
  std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.enabled || !s.printed.insert(kind + (": " + text)).second) return;
  const std::string line = std::string("signalsim: ") + kind + ": " + text + "\n";
  if (s.holding)
    s.held.push_back(line);
  else
    std::cerr << line;
}

}  // namespace

void set_notes_enabled(bool enabled) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().enabled = enabled;
}

void forget_printed_notes() {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().printed.clear();
  state().held.clear();
  state().holding = false;
}

void hold_notes() {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().holding = true;
}

void release_notes() {
  NoteState& s = state();
  std::lock_guard<std::mutex> lock(s.mutex);
  for (const std::string& line : s.held) std::cerr << line;
  s.held.clear();
  s.holding = false;
}

void note_once(const std::string& text) { print_once("note", text); }

void warn_once(const std::string& text) { print_once("warning", text); }

std::string unused_parameters_note(const UnusedParameters& unused) {
  std::string text = unused.file + ": " + std::to_string(unused.keys.size()) +
                     (unused.keys.size() == 1 ? " key" : " keys") + " signalsim does not use: ";
  for (std::size_t i = 0; i < unused.keys.size() && i < kNamesShown; ++i) text += (i ? ", " : "") + unused.keys[i];
  if (unused.keys.size() > kNamesShown)
    text += " (+" + std::to_string(unused.keys.size() - kNamesShown) + " more; all in summary.json parameter_files)";
  return text;
}

}  // namespace signalsim
