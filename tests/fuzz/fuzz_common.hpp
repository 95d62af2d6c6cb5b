// Shared helpers of the libFuzzer targets (tests/fuzz, README "Fuzzing and sanitizers").
// A finding is a crash, a sanitizer report, a leak, an assertion of a target (FUZZ_ASSERT) or an
// exception the loader does not document: targets catch only the documented ones.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace signalsim::fuzz {

/// Aborts (a libFuzzer crash with the input saved) when an invariant of a target does not hold.
#define FUZZ_ASSERT(cond)                                                                  \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      std::fprintf(stderr, "FUZZ_ASSERT failed: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
      std::abort();                                                                        \
    }                                                                                      \
  } while (0)

/// A private directory for this process's temporary input files (under $TMPDIR or /tmp), removed
/// at exit.
inline const std::filesystem::path& work_dir() {
  static const std::filesystem::path dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::filesystem::path d = std::filesystem::path(tmp && *tmp ? tmp : "/tmp") /
                              ("signalsim_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(work_dir(), ec);
    });
    return d;
  }();
  return dir;
}

/// Writes `size` bytes to `path` (replacing it) and returns the path as a string.
inline std::string write_file(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  return path.string();
}

}  // namespace signalsim::fuzz
