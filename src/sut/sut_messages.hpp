// The JSON-lines protocol of an exec: system under test (docs/decider.md "JSON lines"): the text of
// every message signalsim writes (hello, step, bye: one JSON object per line) and the parsing of the
// SUT's replies (a decider's blinker, a light judge's answers). No I/O; sut_process.hpp moves the lines.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/blinker_signals.hpp"
#include "sut/sut_values.hpp"

namespace signalsim {

/// The protocol's version, sent in hello's `protocol`.
inline constexpr int kSutProtocolVersion = 1;

/// A reply that is not one (not JSON, a field missing or of the wrong kind); the message says why.
class SutReplyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// `role` is "decider" or "light_judge". Each text ends with its newline.
std::string sut_hello_message(const SutRun& run, std::string_view role);
std::string sut_step_message(const SutStep& step, const RouteMap& route);
std::string sut_bye_message();

/// A decider's reply line: {"blinker": "none"|"left"|"right"|"hazard"}. Throws SutReplyError.
Blinker parse_decider_reply(const std::string& line);

/// A light judge's reply line: {"lights": [{"tls_id", "decision": "stop"|"go", "reason"?}, ...]}, one
/// entry per light of `step.lights` in that order (tls_id must match). Throws SutReplyError.
std::vector<SutLightAnswer> parse_light_judge_reply(const std::string& line, const SutStep& step);

}  // namespace signalsim
