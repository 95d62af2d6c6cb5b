// Shared helpers of the libFuzzer targets (tests/fuzz, README "Fuzzing and sanitizers").
// A finding is a crash, a sanitizer report, a leak, an assertion of a target (FUZZ_ASSERT) or an
// exception the loader does not document: targets catch only the documented ones.
#pragma once

#include <signal.h>
#include <unistd.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
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

/// A double FuzzedDataProvider never gives: ConsumeFloatingPoint returns finite values only. One of
/// quiet NaN, +infinity, -infinity, -0.0 and the smallest denormal, chosen by one consumed byte.
inline double special_double(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegral<std::uint8_t>() % 5) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return std::numeric_limits<double>::infinity();
    case 2: return -std::numeric_limits<double>::infinity();
    case 3: return -0.0;
    default: return std::numeric_limits<double>::denorm_min();
  }
}

/// A private directory for this process's temporary input files:
/// <build>/tests/fuzz/work/<target>/<pid> (SIGNALSIM_FUZZ_WORK_DIR, set by tests/fuzz/CMakeLists.txt),
/// removed at a normal exit. A crash (abort: no atexit) leaves its directory behind, so at start the
/// directories of processes that no longer run are removed; the pid keeps libFuzzer's -jobs/-fork
/// workers of one target apart.
inline const std::filesystem::path& work_dir() {
  // Never destroyed: a static path object's destructor is registered when its initialiser returns,
  // after the atexit handler below, so it would run first and leave the handler a dead object
  // (the directory then stayed behind after every run).
  static const std::filesystem::path* const dir = [] {
    const std::filesystem::path root = SIGNALSIM_FUZZ_WORK_DIR;
    std::error_code ec;
    std::filesystem::create_directories(root, ec);
    for (const auto& entry : std::filesystem::directory_iterator(root, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
      const long pid = std::strtol(name.c_str(), nullptr, 10);
      if (pid <= 0 || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // still running
      std::filesystem::remove_all(entry.path(), ec);
    }
    auto* d = new std::filesystem::path(root / std::to_string(::getpid()));
    std::filesystem::remove_all(*d, ec);  // a stale one of a dead process whose pid this one got
    std::filesystem::create_directories(*d);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(work_dir(), ignored);
    });
    return d;
  }();
  return *dir;
}

/// Writes `size` bytes to `path` (replacing it) and returns the path as a string.
inline std::string write_file(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  return path.string();
}

}  // namespace signalsim::fuzz
