// File names as SUMO and signalsim resolve them: relative to the folder of the file that names them.
#pragma once

#include <filesystem>
#include <string>

namespace signalsim {

/// `path` when it is absolute (normalised) or `dir` is empty (as written); else `dir`/`path`,
/// normalised. An empty `path` stays empty.
inline std::string resolve_path(const std::string& dir, const std::string& path) {
  const std::filesystem::path p(path);
  if (path.empty()) return path;
  if (p.is_absolute()) return p.lexically_normal().string();
  if (dir.empty()) return path;
  return (std::filesystem::path(dir) / p).lexically_normal().string();
}

/// resolve_path from the folder of `file` (a scenario, sweep or configuration file).
inline std::string resolve_beside(const std::string& file, const std::string& path) {
  if (path.empty()) return path;
  const std::filesystem::path p(path);
  if (p.is_absolute()) return p.lexically_normal().string();
  return (std::filesystem::path(file).parent_path() / p).lexically_normal().string();
}

}  // namespace signalsim
