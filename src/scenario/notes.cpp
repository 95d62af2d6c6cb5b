// Once-per-process notes on stderr.
#include "scenario/notes.hpp"

#include <iostream>
#include <mutex>
#include <set>

namespace signalsim {
namespace {

constexpr std::size_t kNamesShown = 6;  // the rest are counted; summary.json lists all

struct NoteState {
  std::mutex mutex;
  bool enabled = true;
  std::set<std::string> printed;
};

NoteState& state() {
  static NoteState s;
  return s;
}

}  // namespace

void set_notes_enabled(bool enabled) {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().enabled = enabled;
}

void forget_printed_notes() {
  std::lock_guard<std::mutex> lock(state().mutex);
  state().printed.clear();
}

void note_once(const std::string& text) {
  NoteState& s = state();
  std::lock_guard<std::mutex> lock(s.mutex);
  if (!s.enabled || !s.printed.insert(text).second) return;
  std::cerr << "signalsim: note: " << text << "\n";
}

std::string unused_parameters_note(const UnusedParameters& unused) {
  std::string text = unused.file + ": " + std::to_string(unused.keys.size()) +
                     (unused.keys.size() == 1 ? " key" : " keys") + " signalsim does not use: ";
  for (std::size_t i = 0; i < unused.keys.size() && i < kNamesShown; ++i) text += (i ? ", " : "") + unused.keys[i];
  if (unused.keys.size() > kNamesShown)
    text += " (+" + std::to_string(unused.keys.size() - kNamesShown) + " more; all in summary.json parameter_files)";
  return text;
}

}  // namespace signalsim
