// Reading squeue's task lines (slurm_queue.hpp).
#include "batch/slurm/slurm_queue.hpp"

#include <cctype>
#include <set>
#include <string_view>

namespace signalsim {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

bool read_number(std::string_view s, std::size_t& value) {
  if (s.empty() || s.size() > 18) return false;
  value = 0;
  for (const char c : s) {
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    value = value * 10 + static_cast<std::size_t>(c - '0');
  }
  return true;
}

// "3-7,9%2" (the throttle after '%' dropped): every index in it; false when it is not such a list.
bool add_indices(std::string_view text, const std::string& state, TaskStates& states) {
  if (const auto percent = text.find('%'); percent != std::string_view::npos) text = text.substr(0, percent);
  if (text.size() >= 2 && text.front() == '[' && text.back() == ']') text = text.substr(1, text.size() - 2);
  TaskStates found;
  while (!text.empty()) {
    const auto comma = text.find(',');
    const std::string_view part = text.substr(0, comma);
    text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
    std::size_t first = 0, last = 0;
    const auto dash = part.find('-');
    if (dash == std::string_view::npos) {
      if (!read_number(part, first)) return false;
      last = first;
    } else if (!read_number(part.substr(0, dash), first) || !read_number(part.substr(dash + 1), last) || last < first) {
      return false;
    }
    for (std::size_t i = first; i <= last; ++i) found[i] = state;
  }
  for (auto& [index, s] : found) states[index] = s;
  return !found.empty();
}

}  // namespace

TaskStates parse_task_states(const std::string& squeue_output) {
  TaskStates states;
  std::size_t at = 0;
  while (at < squeue_output.size()) {
    const std::size_t end = std::min(squeue_output.find('\n', at), squeue_output.size());
    const std::string_view line = trim(std::string_view(squeue_output).substr(at, end - at));
    at = end + 1;
    const auto bar = line.find('|');
    if (bar == std::string_view::npos) continue;
    const std::string state(trim(line.substr(bar + 1)));
    if (!state.empty()) add_indices(trim(line.substr(0, bar)), state, states);
  }
  return states;
}

bool is_active_task_state(const std::string& state) {
  static const std::set<std::string> active = {
      "PENDING",  "RUNNING",      "CONFIGURING", "COMPLETING",   "SUSPENDED",     "STOPPED",   "REQUEUED",
      "REQUEUE_HOLD", "REQUEUE_FED", "RESIZING", "SIGNALING",  "STAGE_OUT",     "RESV_DEL_HOLD", "SPECIAL_EXIT"};
  return active.count(state) > 0;
}

std::string describe_task_states(const TaskStates& states) {
  std::size_t pending = 0, running = 0;
  for (const auto& [index, state] : states) {
    if (state == "RUNNING" || state == "CONFIGURING" || state == "COMPLETING") ++running;
    else if (is_active_task_state(state)) ++pending;
  }
  if (pending == 0 && running == 0) return "no task pending or running";
  std::string out;
  if (pending) out = std::to_string(pending) + " task" + (pending == 1 ? "" : "s") + " pending";
  if (running)
    out += (out.empty() ? std::to_string(running) + " task" + (running == 1 ? "" : "s") + " running"
                        : ", " + std::to_string(running) + " running");
  return out;
}

}  // namespace signalsim
