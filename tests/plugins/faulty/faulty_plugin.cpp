// Decider plugins that fail on purpose, one fault per build (a FAULT_* definition): the fault tests
// (tests/integration/sut_library_faults_test.sh) check that each ends the run as an error with one
// line naming the SUT and the step. Without a fault the decider answers "none" every step.
#include <csignal>
#include <cstdio>

#include "signalsim/decider_plugin.h"

extern "C" {

uint32_t signalsim_plugin_abi_version(void) {
#ifdef FAULT_WRONG_ABI
  return SIGNALSIM_PLUGIN_ABI_VERSION + 41u;
#else
  return SIGNALSIM_PLUGIN_ABI_VERSION;
#endif
}

void* signalsim_decider_create(const ss_run* run, char* error, size_t error_size) {
#ifdef FAULT_CREATE_FAILS
  std::snprintf(error, error_size, "cannot decide on a route of %zu lanelets", run->lanelet_count);
  return nullptr;
#else
  (void)error;
  (void)error_size;
  return const_cast<ss_run*>(run);
#endif
}

#ifndef FAULT_MISSING_STEP
int signalsim_decider_step(void* decider, const ss_step* step, ss_blinker* blinker, char* error, size_t error_size) {
  (void)decider;
  *blinker = SS_BLINKER_NONE;
#ifdef FAULT_STEP_FAILS
  if (step->time >= 5.0 - 1e-9) {
    std::snprintf(error, error_size, "lost the ego at s=%.1f m", step->ego.s_front);
    return 3;
  }
#endif
#ifdef FAULT_SEGV
  if (step->time >= 3.0 - 1e-9) std::raise(SIGSEGV);
#endif
  (void)step;
  (void)error;
  (void)error_size;
  return 0;
}
#endif

void signalsim_decider_destroy(void* decider) { (void)decider; }

}  // extern "C"
