// Fleet mode's files; see fleet_outputs.hpp.
#include "report/fleet_outputs.hpp"

#include "core/csv.hpp"
#include "core/number_text.hpp"
#include "report/atomic_file.hpp"
#include "scenario/scenario.hpp"  // to_string(Blinker)

namespace signalsim {
namespace {

double mean(double sum, int count) { return count > 0 ? as_written(sum / count, 3) : 0.0; }

nlohmann::ordered_json place_json(const std::string& id, const FleetPlaceStats& p, bool observed) {
  nlohmann::ordered_json j;
  j["id"] = id;
  j["kind"] = p.kind;
  j["signals"] = p.signals;
  j["left"] = p.left;
  j["right"] = p.right;
  j["lead_mean"] = mean(p.lead_sum, p.signals);
  j["lead_min"] = as_written(p.lead_min, 3);
  j["lead_max"] = as_written(p.lead_max, 3);
  if (observed) {
    j["sumo_signalled"] = p.sumo_signalled;
    j["sumo_lead_mean"] = mean(p.sumo_lead_sum, p.sumo_signalled);
  }
  return j;
}

}  // namespace

void write_fleet_events_csv(const std::string& path, const FleetRecord& record) {
  std::string out = "vehicle,time,blinker,s_front,place,place_kind,source\n";
  for (const FleetEvent& e : record.events) {
    out += csv_field(e.vehicle);
    out += ',';
    append_fixed(out, e.time, 3);
    out += ',';
    out += to_string(e.blinker);
    out += ',';
    append_fixed(out, e.s_front, 3);
    out += ',';
    out += csv_field(e.place);
    out += ',';
    out += e.place_kind;
    out += ',';
    out += e.source;
    out += '\n';
  }
  write_file_atomically(path, out);
}

nlohmann::ordered_json fleet_json(const FleetRecord& record) {
  const FleetTotals& t = record.totals;
  const bool observed = !record.set_signals;
  nlohmann::ordered_json j;
  j["version"] = 1;
  j["mode"] = record.set_signals ? "set" : "observe";
  j["country"] = record.country;
  j["vehicles"] = {{"seen", t.vehicles_seen},         {"selected", t.vehicles_selected},
                   {"followed", t.vehicles_followed}, {"left_to_sumo", t.left_to_sumo},
                   {"signalled", t.vehicles_signalled}, {"rerouted", t.rerouted},
                   {"teleports", t.teleports}};
  j["routes"] = {{"distinct", t.distinct_routes}, {"not_understood", t.routes_not_understood}};
  j["vehicle_steps"] = t.vehicle_steps;
  j["events"] = record.events.size();
  int signals = 0, left = 0, right = 0;
  double lead_sum = 0.0;
  nlohmann::ordered_json places = nlohmann::ordered_json::array();
  for (const auto& [id, p] : record.places) {
    places.push_back(place_json(id, p, observed));
    signals += p.signals;
    left += p.left;
    right += p.right;
    lead_sum += p.lead_sum;
  }
  j["signals"] = {{"on", signals}, {"left", left}, {"right", right}, {"lead_mean", mean(lead_sum, signals)}};
  j["places"] = places;
  if (observed) {
    j["sumo"] = {{"agree_steps", t.agree_steps},
                 {"rules_only_steps", t.rules_only_steps},
                 {"sumo_only_steps", t.sumo_only_steps},
                 {"opposite_steps", t.opposite_steps}};
  } else {
    j["sumo"] = nullptr;  // not measured: signalsim set the signals SUMO would have computed
  }
  nlohmann::ordered_json left_examples = nlohmann::ordered_json::array();
  for (const auto& [vehicle, reason] : record.left_examples) left_examples.push_back({{"vehicle", vehicle}, {"reason", reason}});
  j["left_to_sumo_examples"] = left_examples;
  return j;
}

}  // namespace signalsim
