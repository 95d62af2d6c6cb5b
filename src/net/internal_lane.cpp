// SUMO's internal lane ids (see internal_lane.hpp).
#include "net/internal_lane.hpp"

#include <algorithm>
#include <cctype>

namespace signalsim::sumo {

std::string junction_of_internal_lane(std::string_view id) {
  const auto all_digits = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
  };
  for (int group = 0; group < 2; ++group) {
    const std::size_t cut = id.rfind('_');
    if (cut == std::string_view::npos || !all_digits(id.substr(cut + 1))) return {};
    id = id.substr(0, cut);
  }
  if (!id.empty() && id.front() == ':') id.remove_prefix(1);
  return std::string(id);
}

}  // namespace signalsim::sumo
