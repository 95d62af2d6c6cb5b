// Reads a SUMO net file into memory: plain XML, or gzip (detected by its magic bytes 0x1f 0x8b,
// not by its name, so "x.net.xml" may be compressed and "x.net.xml.gz" may be plain).
#pragma once

#include <string>

namespace signalsim::sumo {

/// The (inflated) bytes of the file at `path`.
/// Throws NetError "<path>: <reason>" when the file is missing, unreadable or a corrupt gzip stream.
std::string read_net_file(const std::string& path);

}  // namespace signalsim::sumo
