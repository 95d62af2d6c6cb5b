// Loads the built autoware_core plugin with dlopen and runs its exported C functions: one decider
// per route, stepped along s at a constant speed, its blinker sections (on and off s) collected.
#pragma once

#include <dlfcn.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "signalsim/decider_plugin.h"

namespace signalsim::test {

struct PluginApi {
  void* handle = nullptr;
  uint32_t (*abi_version)() = nullptr;
  const char* (*name)() = nullptr;
  void* (*create)(const ss_run*, char*, size_t) = nullptr;
  int (*step)(void*, const ss_step*, ss_blinker*, char*, size_t) = nullptr;
  void (*destroy)(void*) = nullptr;
};

template <class F>
F symbol(void* handle, const char* name) {
  void* p = dlsym(handle, name);
  if (p == nullptr) throw std::runtime_error(std::string("missing symbol ") + name);
  return reinterpret_cast<F>(p);
}

inline const PluginApi& plugin() {
  static const PluginApi api = [] {
    PluginApi a;
    a.handle = dlopen(SIGNALSIM_AUTOWARE_CORE_PLUGIN, RTLD_NOW | RTLD_LOCAL);
    if (a.handle == nullptr) throw std::runtime_error(dlerror());
    a.abi_version = symbol<decltype(a.abi_version)>(a.handle, "signalsim_plugin_abi_version");
    a.name = symbol<decltype(a.name)>(a.handle, "signalsim_plugin_name");
    a.create = symbol<decltype(a.create)>(a.handle, "signalsim_decider_create");
    a.step = symbol<decltype(a.step)>(a.handle, "signalsim_decider_step");
    a.destroy = symbol<decltype(a.destroy)>(a.handle, "signalsim_decider_destroy");
    return a;
  }();
  return api;
}

/// One decider instance on a run.
class Decider {
 public:
  explicit Decider(const ss_run& run) {
    char error[256] = "";
    handle_ = plugin().create(&run, error, sizeof error);
    if (handle_ == nullptr) throw std::runtime_error(error);
  }
  ~Decider() { plugin().destroy(handle_); }
  Decider(const Decider&) = delete;
  Decider& operator=(const Decider&) = delete;

  /// The blinker with base_link at `s_base` and the signed `speed` [m/s].
  ss_blinker at(double s_base, double speed, double base_link_to_front = 3.7) {
    ss_step step{};
    step.ego.s_base = s_base;
    step.ego.s_front = s_base + base_link_to_front;
    step.ego.speed = speed;
    ss_blinker blinker = SS_BLINKER_HAZARD;
    char error[256] = "";
    if (plugin().step(handle_, &step, &blinker, error, sizeof error) != 0) throw std::runtime_error(error);
    return blinker;
  }

 private:
  void* handle_ = nullptr;
};

/// A section of s where the blinker is on: [on, off).
struct Section {
  ss_blinker blinker = SS_BLINKER_NONE;
  double on = 0.0, off = 0.0;
};

/// Steps base_link from `from` to `to` every 0.01 m at `speed` and returns the sections it is on.
inline std::vector<Section> sections(const ss_run& run, double from, double to, double speed) {
  Decider decider(run);
  std::vector<Section> out;
  ss_blinker last = SS_BLINKER_NONE;
  const long first = static_cast<long>(from * 100.0), end = static_cast<long>(to * 100.0);
  for (long i = first; i <= end; ++i) {
    const double s = static_cast<double>(i) / 100.0;
    const ss_blinker b = decider.at(s, speed);
    if (b != last && last != SS_BLINKER_NONE) out.back().off = s;
    if (b != last && b != SS_BLINKER_NONE) out.push_back({b, s, to});
    last = b;
  }
  return out;
}

}  // namespace signalsim::test
