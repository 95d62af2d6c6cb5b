// The back-ends' factories (libsumo and libtraci cannot share a translation unit, docs/behaviour.md
// §S1); open_session (session_factory.cpp) picks one. Private to src/session.
//
// libsumo lives in a module of its own, libsignalsim_libsumo.so, loaded the first time a command needs
// SUMO in-process: Debian's libsumo pulls in about 220 shared libraries (GDAL, FFmpeg, OpenSceneGraph,
// ...) whose loading and binding costs about 0.15 s, which every command paid at start before (also
// `--version`, `schema`, a batch's parent). The module finds five of signalsim's functions in the
// program (program_exports.map), so both share one interruption state; the program exports nothing
// else. The module and the program must come from the same build: kEmbeddedBackendBuild.
#pragma once

#include <memory>
#include <string>

#include "session/sumo_session.hpp"

namespace signalsim::sumo {

/// What the libsumo module offers: the functions behind open_session (embedded), net_load_error and
/// embedded_sumo_reusable, and the build it came from.
struct EmbeddedBackend {
  const char* build;  ///< SIGNALSIM_BUILD_ID of the module's build: the program refuses another
  std::unique_ptr<SumoSession> (*open)(const SessionConfig& config);
  std::string (*net_load_error)(const std::string& net_path);
  bool (*reusable)();
};

/// The module's one exported function (extern "C"): its EmbeddedBackend. The version in the name
/// changes with EmbeddedBackend or the session interface.
inline constexpr const char* kEmbeddedBackendSymbol = "signalsim_embedded_backend_v4";
/// The build both were compiled in (a random id CMake draws once per build folder): SessionConfig and
/// SumoSession cross the boundary as C++ types, so a module from another build is refused.
inline constexpr const char* kEmbeddedBackendBuild = SIGNALSIM_BUILD_ID;
/// The module's file name: bin/../lib/signalsim/ installed, <build>/lib/signalsim/ in a build tree.
inline constexpr const char* kEmbeddedBackendFile = "libsignalsim_libsumo.so";

/// gui (starts sumo-gui itself) and connect (an existing server).
std::unique_ptr<SumoSession> open_traci_session(const SessionConfig& config);

}  // namespace signalsim::sumo
