// The lib: systems under test; see sut_library.hpp.
#include "sut/sut_library.hpp"

#include <cstdio>

#include "sut/plugin_crash_note.hpp"

namespace signalsim {
namespace {

// "decider lib:d.so at t=12.30 s: the plugin's reason" (at the start: before the first step).
SutError sut_error(const std::string& who, double time, const char* reason) {
  char at[48];
  if (time < 0.0) std::snprintf(at, sizeof at, "at the start");
  else std::snprintf(at, sizeof at, "at t=%.2f s", time);
  const std::string why = reason && *reason ? reason : "no reason given";
  return SutError(who + " " + at + ": " + why);
}

// The plugin's instance for the run (a previous one destroyed first). Throws SutError.
void* create_instance(const PluginLibrary& lib, const std::string& who, const CRun& run, void* previous,
                      char* error, std::size_t size) {
  PluginCallGuard guard(who.c_str(), -1.0);
  if (previous) lib.destroy(previous);
  error[0] = '\0';
  void* instance = lib.create(&run.get(), error, size);
  error[size - 1] = '\0';
  if (!instance) throw sut_error(who, -1.0, *error ? error : "create returned NULL");
  return instance;
}

}  // namespace

LibraryDecider::LibraryDecider(std::shared_ptr<const PluginLibrary> library, const std::string& label)
    : library_(std::move(library)), who_("decider " + label) {}

LibraryDecider::~LibraryDecider() {
  if (!instance_) return;
  PluginCallGuard guard(who_.c_str(), -1.0);
  library_->destroy(instance_);
}

void LibraryDecider::start(const SutRun& run) {
  run_ = std::make_unique<CRun>(run);
  void* previous = instance_;
  instance_ = nullptr;
  instance_ = create_instance(*library_, who_, *run_, previous, error_, sizeof error_);
}

Blinker LibraryDecider::decide(const SutStep& step) {
  const ss_step& in = step_.fill(step);
  ss_blinker answer = SS_BLINKER_NONE;
  error_[0] = '\0';
  int status = 0;
  {
    PluginCallGuard guard(who_.c_str(), step.time);
    status = library_->decider_step(instance_, &in, &answer, error_, sizeof error_);
  }
  error_[sizeof error_ - 1] = '\0';
  if (status != 0) throw sut_error(who_, step.time, *error_ ? error_ : "step returned an error without a reason");
  Blinker blinker = Blinker::None;
  if (!blinker_from_c(static_cast<int>(answer), blinker))
    throw sut_error(who_, step.time, ("answered blinker " + std::to_string(static_cast<int>(answer)) +
                                      ", not one of ss_blinker (0 none, 1 left, 2 right, 3 hazard)").c_str());
  return blinker;
}

LibraryLightJudge::LibraryLightJudge(std::shared_ptr<const PluginLibrary> library, const std::string& label)
    : library_(std::move(library)), who_("light_judge " + label) {}

LibraryLightJudge::~LibraryLightJudge() {
  if (!instance_) return;
  PluginCallGuard guard(who_.c_str(), -1.0);
  library_->destroy(instance_);
}

void LibraryLightJudge::start(const SutRun& run) {
  run_ = std::make_unique<CRun>(run);
  void* previous = instance_;
  instance_ = nullptr;
  instance_ = create_instance(*library_, who_, *run_, previous, error_, sizeof error_);
}

std::vector<SutLightAnswer> LibraryLightJudge::judge(const SutStep& step) {
  const ss_step& in = step_.fill(step);
  answers_.assign(in.light_count, ss_light_answer{SS_LIGHT_GO, {}});
  error_[0] = '\0';
  int status = 0;
  {
    PluginCallGuard guard(who_.c_str(), step.time);
    status = library_->judge_step(instance_, &in, answers_.data(), error_, sizeof error_);
  }
  error_[sizeof error_ - 1] = '\0';
  if (status != 0) throw sut_error(who_, step.time, *error_ ? error_ : "step returned an error without a reason");
  std::vector<SutLightAnswer> out;
  out.reserve(answers_.size());
  for (ss_light_answer& a : answers_) {
    if (a.decision != SS_LIGHT_GO && a.decision != SS_LIGHT_STOP)
      throw sut_error(who_, step.time, ("answered decision " + std::to_string(static_cast<int>(a.decision)) +
                                        ", not one of ss_light_decision (0 go, 1 stop)").c_str());
    a.reason[sizeof a.reason - 1] = '\0';
    out.push_back({a.decision == SS_LIGHT_STOP, a.reason});
  }
  return out;
}

}  // namespace signalsim
