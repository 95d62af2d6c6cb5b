#include "app/inspect.hpp"

#include <cstdio>

#include "core/number_text.hpp"
#include "route/route_builder.hpp"

namespace signalsim {
namespace {

}  // namespace

void print_net_summary(std::ostream& out, const sumo::NetIndex& net) {
  out << "net " << net.path() << ": " << net.edge_count() << " edges, " << net.tl_logics().size()
      << " traffic lights, " << net.roundabouts().size() << " roundabouts, "
      << (net.lefthand() ? "left-hand" : "right-hand") << " traffic\n";
  // The loading rule (net/net_index.hpp): defects are listed; only a route that uses one is refused.
  if (net.defects().empty()) return;
  out << net.defects().size() << " defect(s) recorded; a route that uses the element is refused, unless marked [no route reads it]:\n";
  for (const sumo::NetDefect& d : net.defects()) {
    out << "  " << net.path() << ":" << d.line << ": " << d.element << ": " << d.reason
        << (d.affects_routes ? "" : " [no route reads it]") << "\n";
  }
}

void print_route(std::ostream& out, const sumo::RoutePlan& plan) {
  out << "route: " << plan.map.size() << " lanelets, " << format_text("%.2f", plan.map.length()) << " m, "
      << plan.lane_changes << " lane change(s) planned\n";
  // Where the lane plan put each lane change, and the room it has there (route/lane_change_room.hpp).
  for (const sumo::PlannedLaneChange& c : plan.changes) {
    out << format_text("lane change on edge '%s': lane %d -> %d, a %.2f m shift in %.2f m of room: ", c.edge.c_str(),
                       c.from_lane, c.to_lane, c.shift, c.room)
        << (c.fits ? "fits" : "does not fit")
        << format_text(" (at least %.2f m of lateral motion at %.2f m/s)\n", c.min_length,
                       plan.rooms[c.edge_index].speed);
  }
  out << format_text("%4s %9s %9s  %-18s %-9s %-10s %-8s %7s %-14s %s\n", "#", "s_start", "s_end", "lane", "turn",
                     "roundabout", "junction", "v_max", "light", "params");
  for (std::size_t i = 0; i < plan.map.size(); ++i) {
    const Lanelet& l = plan.map.at(i);
    std::string light = l.traffic_light ? l.traffic_light->tls_id + ":" + std::to_string(l.traffic_light->link_index) : "-";
    std::string params;
    if (l.turn_signal_distance) params += format_text("turn_signal_distance=%.1f ", *l.turn_signal_distance);
    for (const auto& [key, value] : l.params)
      if (key != "turn_signal_distance") params += key + "=" + value + " ";
    if (l.stop_offset > 0.0) params += format_text("stop_offset=%.2f ", l.stop_offset);
    out << format_text("%4zu %9.2f %9.2f  %-18s %-9s %-10s %-8s %7.2f %-14s %s\n", i, l.s_start, l.s_end(),
                       l.lane_id.c_str(), std::string(to_string(l.turn_direction)).c_str(),
                       std::string(to_string(l.roundabout_role)).c_str(),
                       l.junction_id.empty() ? "-" : l.junction_id.c_str(), l.speed_limit, light.c_str(),
                       params.empty() ? "-" : params.c_str());
  }
}

}  // namespace signalsim
