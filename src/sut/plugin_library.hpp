// A C ABI plugin (include/signalsim/decider_plugin.h) loaded into the process: dlopen, the ABI
// version check and the three functions of one role. Loading is all-or-nothing: a library that
// cannot be used throws PluginLoadError with the reason, and nothing of it stays loaded.
#pragma once

#include <stdexcept>
#include <string>

#include <signalsim/decider_plugin.h>

namespace signalsim {

class PluginLoadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class PluginRole { Decider, LightJudge };

class PluginLibrary {
 public:
  using DeciderStep = int (*)(void*, const ss_step*, ss_blinker*, char*, size_t);
  using JudgeStep = int (*)(void*, const ss_step*, ss_light_answer*, char*, size_t);

  /// dlopen(path, RTLD_NOW | RTLD_LOCAL), signalsim_plugin_abi_version() == SIGNALSIM_PLUGIN_ABI_VERSION,
  /// the role's create, step and destroy. Throws PluginLoadError.
  PluginLibrary(const std::string& path, PluginRole role);
  ~PluginLibrary();
  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;

  const std::string& path() const { return path_; }
  /// signalsim_plugin_name(), "" when the plugin does not export it.
  const std::string& name() const { return name_; }

  void* (*create)(const ss_run*, char*, size_t) = nullptr;
  void (*destroy)(void*) = nullptr;
  DeciderStep decider_step = nullptr;  ///< the decider role's step
  JudgeStep judge_step = nullptr;      ///< the light-judge role's step

 private:
  void* symbol(const char* name, bool required) const;

  std::string path_;
  std::string name_;
  void* handle_ = nullptr;
};

}  // namespace signalsim
