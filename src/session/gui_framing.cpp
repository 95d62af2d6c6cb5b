// Framing sumo-gui's view on the junction ahead of the ego (see gui_framing.hpp).
#include "session/gui_framing.hpp"

#include <algorithm>
#include <cmath>

#include <libsumo/libtraci.h>

#include "net/internal_lane.hpp"

namespace signalsim::sumo {
namespace {

constexpr double kLightReach = 80.0;   // [m] a light farther ahead is left out of the frame
constexpr double kMargin = 12.0;       // [m] around the ego and the junctions
constexpr double kNearJunction = 40.0;  // [m] ego to the junction's centre when the view is framed
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

}  // namespace

std::optional<GuiPicture> frame_junction_ahead(const std::string& view, const std::string& ego) {
  GuiPicture picture;
  const std::string lane = libtraci::Vehicle::getLaneID(ego);
  picture.junction = lane.rfind(':', 0) == 0 ? junction_of_internal_lane(lane) : junction_at_end_of(lane);
  if (picture.junction.empty()) return std::nullopt;  // the route ends on this lane
  const libsumo::TraCIPosition at = libtraci::Vehicle::getPosition(ego);
  const libsumo::TraCIPosition centre = libtraci::Junction::getPosition(picture.junction);
  if (std::hypot(centre.x - at.x, centre.y - at.y) > kNearJunction) return std::nullopt;  // not yet
  std::vector<std::string> junctions = {picture.junction};
  if (const std::string lit = light_junction_ahead(ego, picture.light); !lit.empty() && lit != picture.junction)
    junctions.push_back(lit);
  std::vector<libsumo::TraCIPosition> points = {at};
  for (const std::string& junction : junctions)
    for (const libsumo::TraCIPosition& p : libtraci::Junction::getShape(junction).value) points.push_back(p);
  // The view keeps tracking the ego (sumo-gui centres a tracked view when it draws, so the ego is
  // where the picture's caption says, whenever sumo-gui draws it); the zoom is chosen so that the
  // junctions around it fit. (Stopping the tracking and setting an offset was measured to leave the
  // view where sumo-gui last drew it, seconds behind a fast run.)
  double half_width = kMinExtent / 2, half_height = kMinExtent / 2;
  for (const libsumo::TraCIPosition& p : points) {
    half_width = std::max(half_width, std::abs(p.x - at.x) + kMargin);
    half_height = std::max(half_height, std::abs(p.y - at.y) + kMargin);
  }
  const double width = 2 * half_width, height = 2 * half_height;
  const double zoom = libtraci::GUI::getZoom(view);
  libtraci::GUI::setZoom(view, zoom);
  std::vector<libsumo::TraCIPosition> seen = libtraci::GUI::getBoundary(view).value;
  if (seen.size() == 2) {
    const double closer = std::min((seen[1].x - seen[0].x) / width, (seen[1].y - seen[0].y) / height);
    libtraci::GUI::setZoom(view, zoom * closer);
    seen = libtraci::GUI::getBoundary(view).value;
  }
  if (seen.size() == 2) {  // the extent shown, about the ego the view is centred on when drawn
    const double shown_half_width = (seen[1].x - seen[0].x) / 2, shown_half_height = (seen[1].y - seen[0].y) / 2;
    picture.view = {at.x - shown_half_width, at.y - shown_half_height, at.x + shown_half_width,
                    at.y + shown_half_height};
  }
  return picture;
}

}  // namespace signalsim::sumo
