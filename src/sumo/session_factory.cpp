// open_session: the back-end by SessionConfig::backend.
#include "sumo/session_factory.hpp"

#include <cstdlib>
#include <filesystem>

namespace signalsim::sumo {
namespace {
constexpr const char* kDebianSumoHome = "/usr/share/sumo";
}  // namespace

std::string_view to_string(BackendKind kind) {
  switch (kind) {
    case BackendKind::Gui: return "gui";
    case BackendKind::Connect: return "connect";
    case BackendKind::Embedded: break;
  }
  return "embedded";
}

std::unique_ptr<SumoSession> open_session(const SessionConfig& config) {
  // SUMO validates its XML inputs against the schemas under SUMO_HOME, else it looks them up on the
  // web (slow, and a warning per run): Debian installs them in /usr/share/sumo.
  if (std::getenv("SUMO_HOME") == nullptr && std::filesystem::is_directory(kDebianSumoHome))
    setenv("SUMO_HOME", kDebianSumoHome, 0);
  if (config.backend.kind == BackendKind::Embedded) return open_embedded_session(config);
  return open_traci_session(config);
}

}  // namespace signalsim::sumo
