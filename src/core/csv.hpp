// CSV text (RFC 4180) as signalsim writes and reads it (results.csv, fleet_events.csv, compare's
// tables, timeline.csv read back): quoting one field, and splitting a whole text into records of
// fields. Nothing here knows any column.
#pragma once

#include <string>
#include <vector>

namespace signalsim {

/// `text` as one CSV field: as it is, or in double quotes (inner quotes doubled) when it holds a
/// comma, a quote or a line break.
std::string csv_field(const std::string& text);

/// The records of a CSV text, each a list of fields (quotes removed). Lines end with \n or \r\n; a
/// last line without a line break is a record too. Never throws.
std::vector<std::vector<std::string>> parse_csv(const std::string& text);

}  // namespace signalsim
