// The back-ends' names as the command line, summary.json and messages spell them (SUMO-free).
#include "session/sumo_session.hpp"

namespace signalsim::sumo {

std::string_view to_string(BackendKind kind) {
  switch (kind) {
    case BackendKind::Gui: return "gui";
    case BackendKind::Connect: return "connect";
    case BackendKind::Embedded: break;
  }
  return "embedded";
}

}  // namespace signalsim::sumo
