// The exec: adapters; see sut_exec.hpp.
#include "sut/sut_exec.hpp"

#include <filesystem>

#include "sut/sut_messages.hpp"
#include "sut/sut_text.hpp"

namespace signalsim {

ExecChannel::ExecChannel(const SutSpec& spec, std::string role) : spec_(spec), role_(std::move(role)) {
  argv_ = split_command(spec_.target);
  program_ = find_program(argv_.front(), spec_.base_dir);
  if (program_.empty())
    throw SutProcessError("'" + argv_.front() + "' is not an executable file" +
                          (argv_.front().find('/') == std::string::npos ? " on PATH" : " (relative to " + spec_.base_dir + ")"));
}

SutError ExecChannel::error(const std::string& when, const std::string& reason) const {
  return SutError(role_ + " " + spec_.text + " " + when + ": " + reason);
}

std::string ExecChannel::step_when(const SutStep& step) const { return "at t=" + time_text(step.time) + " s"; }

void ExecChannel::launch(const std::string& out_dir) {
  const std::string err = (std::filesystem::path(out_dir.empty() ? "." : out_dir) / (role_ + ".stderr.txt")).string();
  try {
    std::filesystem::create_directories(std::filesystem::path(err).parent_path());
    process_ = std::make_unique<SutProcess>(program_, argv_, spec_.base_dir, err);
  } catch (const SutProcessError& e) {
    throw error("at start", e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    throw error("at start", e.what());
  }
}

void ExecChannel::start(const SutRun& run) {
  timeout_ = run.timeout;
  route_ = run.route;
  if (!process_) launch(run.out_dir);
  try {
    process_->write(sut_hello_message(run, role_), timeout_);
  } catch (const SutProcessError& e) {
    process_.reset();  // killed and reaped
    throw error("at hello", e.what());
  }
}

std::string ExecChannel::exchange(const SutStep& step) {
  const std::string when = step_when(step);
  try {
    if (!process_) throw SutProcessError("not started");
    if (process_->has_unread_output())
      throw SutProcessError("wrote a line no step asked for (after its reply " + last_step_ + ")");
    process_->write(sut_step_message(step, *route_), timeout_);
    std::string reply = process_->read_line(timeout_);
    if (process_->has_buffered_output()) throw SutProcessError("wrote more than one line for the step");
    last_step_ = when;
    return reply;
  } catch (const SutProcessError& e) {
    process_.reset();  // killed and reaped
    throw error(when, e.what());
  }
}

void ExecChannel::finish() {
  if (!process_) return;
  try {
    process_->write(sut_bye_message(), timeout_);
    const std::string rest = process_->close(timeout_);
    if (rest.find_first_not_of(" \t\r\n") != std::string::npos)
      throw SutProcessError("wrote a line no step asked for (after its reply " + last_step_ + ")");
  } catch (const SutProcessError& e) {
    process_.reset();
    throw error("at bye", e.what());
  }
  process_.reset();
}

Blinker ExecDecider::decide(const SutStep& step) {
  const std::string reply = channel_.exchange(step);
  try {
    return parse_decider_reply(reply);
  } catch (const SutReplyError& e) {
    throw channel_.error(channel_.step_when(step), e.what());
  }
}

std::vector<SutLightAnswer> ExecLightJudge::judge(const SutStep& step) {
  const std::string reply = channel_.exchange(step);
  try {
    return parse_light_judge_reply(reply, step);
  } catch (const SutReplyError& e) {
    throw channel_.error(channel_.step_when(step), e.what());
  }
}

}  // namespace signalsim
