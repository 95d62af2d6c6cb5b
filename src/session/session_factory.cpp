// open_session: the back-end by SessionConfig::backend; net_load_error: SUMO loads the net alone. The
// embedded back-end is the libsumo module, loaded on first use (session_factory.hpp).
#include "session/session_factory.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include "core/program_location.hpp"
#include "session/interruption.hpp"

#ifndef SIGNALSIM_INSTALL_MODULES_FROM_BIN
#define SIGNALSIM_INSTALL_MODULES_FROM_BIN "../lib/signalsim"
#endif

namespace signalsim::sumo {
namespace fs = std::filesystem;
namespace {
constexpr const char* kDebianSumoHome = "/usr/share/sumo";

// SUMO validates its XML inputs against the schemas under SUMO_HOME, else it looks them up on the
// web (slow, and a warning per run): Debian installs them in /usr/share/sumo.
void default_sumo_home() {
  if (std::getenv("SUMO_HOME") == nullptr && std::filesystem::is_directory(kDebianSumoHome))
    setenv("SUMO_HOME", kDebianSumoHome, 0);
}

// The module beside an installed binary, else in the build tree above the binary.
fs::path embedded_backend_file() {
  std::error_code ec;
  const fs::path exe = running_binary();
  if (exe.empty()) throw SumoError("cannot load signalsim's libsumo module: /proc/self/exe cannot be read to find it");
  const fs::path bin = exe.parent_path();
  const fs::path installed = (bin / SIGNALSIM_INSTALL_MODULES_FROM_BIN / kEmbeddedBackendFile).lexically_normal();
  if (fs::is_regular_file(installed, ec)) return installed;
  if (const fs::path tree = build_tree_above(bin); !tree.empty()) return tree / "lib" / "signalsim" / kEmbeddedBackendFile;
  return installed;
}

const EmbeddedBackend* loaded_backend = nullptr;

const EmbeddedBackend& embedded_backend() {
  if (loaded_backend) return *loaded_backend;
  throw_if_interrupted();  // nothing of SUMO is loaded for a run that is already over
  const fs::path file = embedded_backend_file();
  // Never closed: sessions and SUMO's own state live in it until the process ends.
  void* module = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (module == nullptr) throw SumoError(std::string("cannot load signalsim's libsumo module: ") + dlerror());
  using Entry = const EmbeddedBackend* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(module, kEmbeddedBackendSymbol));
  if (entry == nullptr) throw SumoError(file.string() + " has no " + kEmbeddedBackendSymbol + " (built by another signalsim?)");
  const EmbeddedBackend* backend = entry();
  if (std::string(backend->build) != kEmbeddedBackendBuild)
    throw SumoError(file.string() + " was built with another signalsim (build " + backend->build + ", this program " +
                    kEmbeddedBackendBuild + "): install both from one build");
  loaded_backend = backend;
  return *loaded_backend;
}

}  // namespace

std::string net_load_error(const std::string& net_path) {
  default_sumo_home();
  return embedded_backend().net_load_error(net_path);
}

void load_embedded_backend() { embedded_backend(); }

bool embedded_sumo_reusable() { return loaded_backend == nullptr || loaded_backend->reusable(); }

std::unique_ptr<SumoSession> open_session(const SessionConfig& config) {
  default_sumo_home();
  if (config.backend.kind == BackendKind::Embedded) return embedded_backend().open(config);
  return open_traci_session(config);
}

}  // namespace signalsim::sumo
