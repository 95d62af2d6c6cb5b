// printf-style formatting into a std::string, for the batch room's short messages and file names.
#pragma once

#include <cstdio>
#include <string>

namespace signalsim {

/// snprintf into a string (at most 255 characters: names, counts, durations).
template <typename... Args>
std::string format_text(const char* fmt, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace signalsim
