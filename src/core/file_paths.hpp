// File names as SUMO and signalsim resolve them: relative to the folder of the file that names them;
// and what keeps a name from being an input file signalsim can read.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>

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

/// What keeps `path` from being an input file, "" when it is a regular file (a link is followed):
/// "not found", "is a folder, not a file", "is a named pipe (FIFO), not a file", "is a device, not a
/// file", "is a socket, not a file". Looks at it without opening it (a FIFO would block).
inline std::string input_file_problem(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_regular_file(status)) return "";
  if (!fs::exists(status)) return "not found";
  if (fs::is_directory(status)) return "is a folder, not a file";
  if (fs::is_fifo(status)) return "is a named pipe (FIFO), not a file";
  if (fs::is_block_file(status) || fs::is_character_file(status)) return "is a device, not a file";
  if (fs::is_socket(status)) return "is a socket, not a file";
  return "is not a regular file";
}

}  // namespace signalsim
