// Framing sumo-gui's view on the junction ahead of the ego (see gui_framing.hpp).
#include "session/gui_framing.hpp"

#include <algorithm>

#include <libsumo/libtraci.h>

namespace signalsim::sumo {
namespace {

constexpr double kLightReach = 80.0;   // [m] a light farther ahead is left out of the frame
constexpr double kMargin = 12.0;       // [m] around the ego and the junctions
constexpr double kMinExtent = 60.0;    // [m] the narrowest view: a car and its lamps still visible

// The junction of the first internal lane of `lane`'s links (the junction at its end); "" when none.
std::string junction_at_end_of(const std::string& lane) {
  for (const libsumo::TraCIConnection& link : libtraci::Lane::getLinks(lane))
    if (!link.approachedInternal.empty()) return junction_of_internal_lane(link.approachedInternal);
  return "";
}

// The junction of the next light ahead within kLightReach (its link's internal lane), "" when none.
std::string light_junction_ahead(const std::string& ego, std::string& light) {
  const std::vector<libsumo::TraCINextTLSData> lights = libtraci::Vehicle::getNextTLS(ego);
  if (lights.empty() || lights.front().dist > kLightReach) return "";
  const libsumo::TraCINextTLSData& next = lights.front();
  const auto links = libtraci::TrafficLight::getControlledLinks(next.id);
  if (next.tlIndex < 0 || next.tlIndex >= static_cast<int>(links.size())) return "";
  for (const libsumo::TraCILink& link : links[next.tlIndex])
    if (!link.viaLane.empty()) {
      light = next.id;
      return junction_of_internal_lane(link.viaLane);
    }
  return "";
}

struct Box {
  double x_min = 0, y_min = 0, x_max = 0, y_max = 0;
  void add(double x, double y) {
    x_min = std::min(x_min, x), y_min = std::min(y_min, y);
    x_max = std::max(x_max, x), y_max = std::max(y_max, y);
  }
  // Widened by `margin` on each side, then to `min_extent` about its centre.
  void widen(double margin, double min_extent) {
    x_min -= margin, y_min -= margin, x_max += margin, y_max += margin;
    for (auto [lo, hi] : {std::pair{&x_min, &x_max}, std::pair{&y_min, &y_max}})
      if (const double lack = min_extent - (*hi - *lo); lack > 0) *lo -= lack / 2, *hi += lack / 2;
  }
};

}  // namespace

std::string junction_of_internal_lane(const std::string& lane) {
  std::string id = lane.rfind(':', 0) == 0 ? lane.substr(1) : lane;
  for (int part = 0; part < 2; ++part) {
    const auto cut = id.rfind('_');
    if (cut == std::string::npos || cut == 0) break;
    id.erase(cut);
  }
  return id;
}

GuiPicture frame_junction_ahead(const std::string& view, const std::string& ego) {
  GuiPicture picture;
  const std::string lane = libtraci::Vehicle::getLaneID(ego);
  picture.junction = lane.rfind(':', 0) == 0 ? junction_of_internal_lane(lane) : junction_at_end_of(lane);
  if (picture.junction.empty()) return picture;  // the route ends on this lane: the view keeps the ego
  const libsumo::TraCIPosition at = libtraci::Vehicle::getPosition(ego);
  Box box{at.x, at.y, at.x, at.y};
  std::vector<std::string> junctions = {picture.junction};
  if (const std::string lit = light_junction_ahead(ego, picture.light); !lit.empty() && lit != picture.junction)
    junctions.push_back(lit);
  for (const std::string& junction : junctions)
    for (const libsumo::TraCIPosition& p : libtraci::Junction::getShape(junction).value) box.add(p.x, p.y);
  box.widen(kMargin, kMinExtent);
  libtraci::GUI::trackVehicle(view, "");  // "" stops tracking: the view stays where it is set
  libtraci::GUI::setBoundary(view, box.x_min, box.y_min, box.x_max, box.y_max);
  const libsumo::TraCIPositionVector shown = libtraci::GUI::getBoundary(view);
  for (const libsumo::TraCIPosition& corner : shown.value) picture.view.insert(picture.view.end(), {corner.x, corner.y});
  return picture;
}

}  // namespace signalsim::sumo
