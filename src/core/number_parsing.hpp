// Numbers and text for SUMO: strict text -> number conversion for values read from SUMO files
// (attributes, <param> values), and numbers written for SUMO's command line or for messages.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace signalsim {

/// The whole of `text` (surrounding blanks allowed, a leading '+' allowed) as a finite double,
/// else nullopt ("", "abc", "1.5m", "nan" and "inf" do not parse).
std::optional<double> parse_double(std::string_view text);

/// The whole of `text` (surrounding blanks allowed, a leading '+' allowed) as an int, else nullopt.
std::optional<int> parse_int(std::string_view text);

/// `v` with every digit it has (17 significant): what SUMO is given, so it reads back the same double.
std::string exact_number(double v);
/// `v` as a person reads it ("0.1", "120", "3.25"): for messages and reports.
std::string short_number(double v);

}  // namespace signalsim
