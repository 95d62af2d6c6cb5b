// SUMO's internal lane ids (the lanes inside a junction, ":<junction>_<link>_<lane>"): what they name.
#pragma once

#include <string>
#include <string_view>

namespace signalsim::sumo {

/// ":<junction>_<edge>_<lane>" -> "<junction>": strips the last two "_<int>" groups (junction ids may
/// contain '_', docs/behaviour.md §S2) and the leading ':'. Empty when the id has another form.
std::string junction_of_internal_lane(std::string_view id);

}  // namespace signalsim::sumo
