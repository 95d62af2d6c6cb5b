// open_session: the back-end by SessionConfig::backend; net_load_error: SUMO loads the net alone.
#include "session/session_factory.hpp"

#include <cstdlib>
#include <filesystem>

namespace signalsim::sumo {
namespace {
constexpr const char* kDebianSumoHome = "/usr/share/sumo";

// SUMO validates its XML inputs against the schemas under SUMO_HOME, else it looks them up on the
// web (slow, and a warning per run): Debian installs them in /usr/share/sumo.
void default_sumo_home() {
  if (std::getenv("SUMO_HOME") == nullptr && std::filesystem::is_directory(kDebianSumoHome))
    setenv("SUMO_HOME", kDebianSumoHome, 0);
}

}  // namespace

std::string net_load_error(const std::string& net_path) {
  default_sumo_home();
  return embedded_net_load_error(net_path);
}

std::unique_ptr<SumoSession> open_session(const SessionConfig& config) {
  default_sumo_home();
  if (config.backend.kind == BackendKind::Embedded) return open_embedded_session(config);
  return open_traci_session(config);
}

}  // namespace signalsim::sumo
