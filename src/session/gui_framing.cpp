// Framing sumo-gui's view on the junction ahead of the ego (see gui_framing.hpp).
#include "session/gui_framing.hpp"

#include <algorithm>

#include <libsumo/libtraci.h>

#include "net/internal_lane.hpp"

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

GuiPicture frame_junction_ahead(const std::string& view, const std::string& ego) {
  GuiPicture picture;
  const std::string lane = libtraci::Vehicle::getLaneID(ego);
  picture.junction = lane.rfind(':', 0) == 0 ? junction_of_internal_lane(lane) : junction_at_end_of(lane);
  if (picture.junction.empty()) return picture;  // the route ends on this lane: the view keeps the ego
  const libsumo::TraCIPosition at = libtraci::Vehicle::getPosition(ego);
  std::vector<std::string> junctions = {picture.junction};
  if (const std::string lit = light_junction_ahead(ego, picture.light); !lit.empty() && lit != picture.junction)
    junctions.push_back(lit);
  std::vector<libsumo::TraCIPosition> points = {at};
  for (const std::string& junction : junctions)
    for (const libsumo::TraCIPosition& p : libtraci::Junction::getShape(junction).value) points.push_back(p);
  Box box{at.x, at.y, at.x, at.y};
  for (const libsumo::TraCIPosition& p : points) box.add(p.x, p.y);
  box.widen(kMargin, kMinExtent);
  const double cx = (box.x_min + box.x_max) / 2, cy = (box.y_min + box.y_max) / 2;
  const double width = box.x_max - box.x_min, height = box.y_max - box.y_min;
  libtraci::GUI::trackVehicle(view, "");  // "" stops tracking: the view stays where it is set
  // The zoom that fits the box: the extent shown at the present zoom (getBoundary right after a
  // setZoom; after setBoundary sumo-gui 1.15 reports the box asked for, not what it draws, about twice
  // as wide) scales inversely with the zoom. (A turned view would fit the approach along the picture's
  // long side, but sumo-gui 1.15 leaves out what lies outside the unturned view.)
  libtraci::GUI::setOffset(view, cx, cy);
  const double zoom = libtraci::GUI::getZoom(view);
  libtraci::GUI::setZoom(view, zoom);
  std::vector<libsumo::TraCIPosition> seen = libtraci::GUI::getBoundary(view).value;
  if (seen.size() == 2) {
    const double closer = std::min((seen[1].x - seen[0].x) / width, (seen[1].y - seen[0].y) / height);
    libtraci::GUI::setZoom(view, zoom * closer);
    seen = libtraci::GUI::getBoundary(view).value;
  }
  for (const libsumo::TraCIPosition& corner : seen) picture.view.insert(picture.view.end(), {corner.x, corner.y});
  return picture;
}

}  // namespace signalsim::sumo
