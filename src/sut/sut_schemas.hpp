// The JSON Schemas (draft-07) of the JSON-lines protocol (docs/decider.md "JSON lines"): what
// signalsim writes to an exec: decider or light judge (hello, step, bye) and what each role replies.
// `signalsim schema decider-request|decider-reply|light-judge-request|light-judge-reply` prints them.
#pragma once

#include <string>

namespace signalsim {

/// `role` "decider" or "light_judge": one line signalsim writes (hello, step or bye).
std::string sut_request_schema(const std::string& role);
/// One reply line of the role.
std::string sut_reply_schema(const std::string& role);

}  // namespace signalsim
