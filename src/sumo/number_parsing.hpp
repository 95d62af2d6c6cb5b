// Strict text -> number conversion for values read from SUMO files (attributes, <param> values).
#pragma once

#include <optional>
#include <string_view>

namespace signalsim::sumo {

/// The whole of `text` (surrounding blanks allowed, a leading '+' allowed) as a finite double,
/// else nullopt ("", "abc", "1.5m", "nan" and "inf" do not parse).
std::optional<double> parse_double(std::string_view text);

/// The whole of `text` (surrounding blanks allowed, a leading '+' allowed) as an int, else nullopt.
std::optional<int> parse_int(std::string_view text);

}  // namespace signalsim::sumo
