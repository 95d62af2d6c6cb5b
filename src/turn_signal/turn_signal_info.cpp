#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

std::string_view to_string(RequestSource source) {
  switch (source) {
    case RequestSource::Intersection: return "intersection";
    case RequestSource::RoundaboutEntry: return "roundabout_entry";
    case RequestSource::RoundaboutExit: return "roundabout_exit";
    case RequestSource::LaneChange: return "lane_change";
    case RequestSource::Avoidance: return "avoidance";
    case RequestSource::PullOut: return "pull_out";
    case RequestSource::PullOver: return "pull_over";
    case RequestSource::Sumo: return "sumo";
    case RequestSource::Sut: return "sut";
    case RequestSource::None: break;
  }
  return "none";
}

std::string_view to_string(TurnIndicator command) {
  switch (command) {
    case TurnIndicator::Disable: return "disable";
    case TurnIndicator::EnableLeft: return "left";
    case TurnIndicator::EnableRight: return "right";
    case TurnIndicator::NoCommand: break;
  }
  return "no_command";
}

}  // namespace signalsim
