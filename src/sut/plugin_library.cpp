// Loading a C ABI plugin; see plugin_library.hpp.
#include "sut/plugin_library.hpp"

#include <dlfcn.h>


namespace signalsim {

PluginLibrary::PluginLibrary(const std::string& path, PluginRole role) : path_(path) {
  dlerror();
  handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* why = dlerror();
    throw PluginLoadError(why ? why : "dlopen failed");
  }
  try {
    auto version = reinterpret_cast<uint32_t (*)()>(symbol("signalsim_plugin_abi_version", true));
    const uint32_t found = version();
    if (found != SIGNALSIM_PLUGIN_ABI_VERSION)
      throw PluginLoadError("built against plugin ABI version " + std::to_string(found) + ", signalsim speaks version " +
                            std::to_string(SIGNALSIM_PLUGIN_ABI_VERSION) +
                            " (rebuild it against this signalsim's include/signalsim/decider_plugin.h)");
    if (auto name = reinterpret_cast<const char* (*)()>(symbol("signalsim_plugin_name", false)))
      if (const char* text = name()) name_ = text;
    const bool decider = role == PluginRole::Decider;
    const std::string prefix = decider ? "signalsim_decider_" : "signalsim_light_judge_";
    create = reinterpret_cast<void* (*)(const ss_run*, char*, size_t)>(symbol((prefix + "create").c_str(), true));
    destroy = reinterpret_cast<void (*)(void*)>(symbol((prefix + "destroy").c_str(), true));
    void* step = symbol((prefix + "step").c_str(), true);
    if (decider) decider_step = reinterpret_cast<DeciderStep>(step);
    else judge_step = reinterpret_cast<JudgeStep>(step);
  } catch (...) {
    dlclose(handle_);
    throw;
  }
}

PluginLibrary::~PluginLibrary() {
  if (handle_) dlclose(handle_);
}

void* PluginLibrary::symbol(const char* name, bool required) const {
  void* found = dlsym(handle_, name);
  if (!found && required)
    throw PluginLoadError(std::string("does not export ") + name + " (include/signalsim/decider_plugin.h; extern \"C\" in C++)");
  return found;
}

}  // namespace signalsim
