// Reads a SUMO net file into memory: plain XML, or gzip (detected by its magic bytes 0x1f 0x8b,
// not by its name, so "x.net.xml" may be compressed and "x.net.xml.gz" may be plain); or only its
// driving side, from the file's beginning.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace signalsim::sumo {

/// The most text a net file (or a sumocfg) may hold, plain or inflated from gzip: 512 MiB (a real
/// city's net holds a few tens of MiB; Bad Hersfeld's 23 MiB). A gzip bomb stops at it.
inline constexpr std::size_t kMaxNetText = std::size_t{512} << 20;

/// The (inflated) bytes of the file at `path`.
/// Throws NetError "<path>: <reason>" when the file is missing, is not a regular file (a folder, a
/// named pipe: never opened), is unreadable, a corrupt gzip stream, or holds more than `max_text`.
std::string read_net_file(const std::string& path, std::size_t max_text = kMaxNetText);

/// Whether the net at `path` (plain or gzip) is for left-hand traffic: its root <net>'s `lefthand`
/// (false when it has none), read from the file's first MiB at most. nullopt when the file cannot be
/// read, has no <net> root there, or the value is not a SUMO boolean: loading the net says why.
/// Never throws.
std::optional<bool> read_net_lefthand(const std::string& path);

}  // namespace signalsim::sumo
