// comparison.csv rows and the screen summary of `signalsim compare`; see comparison.hpp.
#include "batch/comparison.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <limits>
#include <map>

#include "core/csv.hpp"
#include "report/signal_sections.hpp"
#include "report/outputs.hpp"

namespace signalsim {
namespace {

using Json = nlohmann::ordered_json;
using Row = std::vector<std::string>;

std::size_t column(const std::string& name) {
  const auto& columns = comparison_columns();
  return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
}

// A number as the other outputs write it: rounded to 1 mm, spelled as JSON ("189.6").
std::string number_text(double v) { return Json(as_written(v, 3)).dump(); }

std::string cell_of(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  return v.dump();
}

// The number-th entry (from 1) of `kind` in the run's metrics, or nullptr.
const Json* metric_of(const DriverRun& run, const ComparedItem& item, int number) {
  if (!run.summary.contains("metrics")) return nullptr;
  const Json& metrics = run.summary["metrics"];
  const bool light = item.kind == "light";
  const char* list = light ? "lights" : "sections";
  if (!metrics.contains(list) || !metrics[list].is_array()) return nullptr;
  int seen = 0;
  for (const Json& entry : metrics[list])
    if ((light || entry.value("kind", "") == item.kind) && ++seen == number) return &entry;
  return nullptr;
}

int number_of(const ComparedItem& item) {
  std::size_t digits = item.name.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(item.name[digits - 1]))) --digits;
  return digits < item.name.size() ? std::stoi(item.name.substr(digits)) : 0;
}

// Where an item's measuring stretch ends (base_link leaves a section; a light is left behind 2 m past
// its line); it begins where the previous item of its kind (section or light) ended.
double measured_end(const ComparedItem& item, double b2f) {
  return item.kind == "light" ? item.s_end + 2.0 : item.s_end + b2f;
}

// Notes for one item of one run (see the file comment of comparison.hpp).
std::string notes_of(const DriverRun& run, const Json* metric, double window_from, double window_to) {
  std::vector<std::string> notes;
  if (metric && !metric->value("reached", true)) notes.push_back("not reached");
  if (run.summary.contains("off_plan"))
    for (const Json& o : run.summary["off_plan"]) {
      const double from = o.value("s_from", 0.0), to = o.value("s_to", 0.0);
      if (to <= window_from || from > window_to) continue;
      notes.push_back("on " + o.value("lane", std::string()) + " (planned " + o.value("planned_lane", std::string()) +
                      ") at s " + fixed(from, 1) + "-" + fixed(to, 1));
    }
  if (run.summary.contains("counts") && run.summary["counts"].value("off_route_steps", 0) > 0)
    notes.push_back(std::to_string(run.summary["counts"].value("off_route_steps", 0)) + " steps off the route");
  std::string out;
  for (const std::string& n : notes) out += (out.empty() ? "" : "; ") + n;
  return out;
}

std::string expectations_of(const DriverRun& run) {
  if (!run.summary.contains("expectations") || !run.summary["expectations"].is_array()) return "";
  int passed = 0, total = 0;
  for (const Json& e : run.summary["expectations"]) {
    ++total;
    passed += e.value("passed", false);
  }
  return std::to_string(passed) + "/" + std::to_string(total);
}

Row item_row(const ScenarioComparison& sc, const ComparedItem* item, const DriverRun& run, double window_from) {
  Row row(comparison_columns().size());
  row[column("scenario")] = sc.scenario;
  row[column("driver")] = run.driver;
  row[column("status")] = run.status;
  row[column("run_dir")] = run.run_dir;
  if (item) {
    row[column("section")] = item->name;
    row[column("kind")] = item->kind;
    row[column("id")] = item->id;
    row[column("s")] = number_text(item->s);
    if (item->kind != "light") row[column("blinker")] = std::string(to_string(item->blinker));
  }
  if (run.status == "error") {
    row[column("error")] = run.error;
    return row;
  }
  row[column("expectations")] = expectations_of(run);
  if (!item) {
    row[column("notes")] = "no sections or lights on the route";
    return row;
  }
  const Json* metric = metric_of(run, *item, number_of(*item));
  if (!metric || metric->value("id", "") != item->id) {
    row[column("status")] = "error";
    row[column("error")] = "the run's metrics have no " + item->name + " at " + item->id;
    return row;
  }
  // blinker_at_start: the section metric (report/section_metrics.hpp), empty when not reached
  const char* const fields[] = {"lead_distance",       "lead_time",           "time_on",  "missed", "blinker_at_start",
                                "state_at_line",       "red_light_violation", "stop_position_error", "decision"};
  for (const char* field : fields)
    if (metric->contains(field)) row[column(field)] = cell_of((*metric)[field]);
  row[column("notes")] = notes_of(run, metric, window_from, measured_end(*item, sc.base_link_to_front));
  return row;
}

// One driver's cell on the screen.
std::string screen_cell(const Row& r) {
  const auto cell = [&](const char* name) { return r[column(name)]; };
  std::string text;
  if (cell("status") == "error") return "error";
  const std::string shown = cell("blinker_at_start");
  if (cell("notes").find("not reached") != std::string::npos) {
    text = "not reached";
  } else if (cell("kind") == "light") {
    if (cell("red_light_violation") == "true") text = "RED crossed";
    else if (!cell("stop_position_error").empty()) text = "stop " + cell("stop_position_error") + " m";
    else if (!cell("state_at_line").empty()) text = "through at " + cell("state_at_line");
    else text = "-";
  } else if (cell("blinker") == "none") {
    text = shown == "none" || shown.empty() ? "-" : shown + " on";
  } else if (cell("missed") == "true") {
    text = "missed";
    if (!cell("lead_distance").empty()) text += " (late, " + cell("lead_distance") + " m)";
    else if (!shown.empty() && shown != "none") text += " (" + shown + " on)";
  } else if (!cell("lead_distance").empty()) {
    text = "lead " + cell("lead_distance") + " m " + cell("lead_time") + " s";
  }
  if (cell("notes").find("planned") != std::string::npos) text += " *";
  return text;
}

std::string padded(std::string text, std::size_t width) {
  if (text.size() > width) text = text.substr(0, width - 1) + "~";
  return text + std::string(width - text.size() + 1, ' ');
}

}  // namespace

std::vector<ComparedItem> compared_items(const RouteMap& route, const TurnSignalParameters& params) {
  std::vector<ComparedItem> out;
  std::map<std::string, int> counters;
  for (const SignalSection& s : signal_sections(route, params))
    out.push_back({s.kind + std::to_string(++counters[s.kind]), s.kind, s.id, s.s_start, s.s_end, s.blinker});
  for (const Lanelet& l : route.lanelets())
    if (!l.is_internal && l.traffic_light)
      out.push_back({"light" + std::to_string(++counters["light"]), "light", l.traffic_light->tls_id, l.stop_line_s(),
                     l.stop_line_s(), Blinker::None});
  // By route s; at the same s the stop line (end of the approach) comes before the junction's section.
  std::stable_sort(out.begin(), out.end(), [](const ComparedItem& a, const ComparedItem& b) {
    if (a.s != b.s) return a.s < b.s;
    return a.kind == "light" && b.kind != "light";
  });
  return out;
}

const std::vector<std::string>& comparison_columns() {
  static const std::vector<std::string> columns = {
      "scenario",      "section",          "kind",          "id",
      "s",             "blinker",          "driver",        "status",
      "expectations",  "lead_distance",    "lead_time",     "time_on",
      "missed",        "blinker_at_start", "state_at_line", "red_light_violation",
      "stop_position_error", "decision",   "notes",         "run_dir",
      "error"};
  return columns;
}

std::vector<Row> comparison_rows(const std::vector<ScenarioComparison>& scenarios) {
  std::vector<Row> rows;
  for (const ScenarioComparison& sc : scenarios) {
    if (sc.items.empty()) {
      for (const DriverRun& run : sc.runs) rows.push_back(item_row(sc, nullptr, run, 0.0));
      continue;
    }
    // A section is measured from the previous section's end, a light from the previous light's.
    double section_from = -std::numeric_limits<double>::infinity(), light_from = section_from;
    for (const ComparedItem& item : sc.items) {
      double& from = item.kind == "light" ? light_from : section_from;
      for (const DriverRun& run : sc.runs) rows.push_back(item_row(sc, &item, run, from));
      from = measured_end(item, sc.base_link_to_front);
    }
  }
  return rows;
}

std::string comparison_csv(const std::vector<ScenarioComparison>& scenarios) {
  std::string out;
  const auto line = [&out](const Row& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + csv_field(cells[i]);
    out += "\n";
  };
  line(comparison_columns());
  for (const Row& row : comparison_rows(scenarios)) line(row);
  return out;
}

std::string comparison_screen(const std::vector<ScenarioComparison>& scenarios, std::size_t max_lines) {
  const std::vector<Row> rows = comparison_rows(scenarios);
  // One column per driver, in run order (sut, signalsim, sumo; or signalsim, sumo).
  std::vector<std::string> drivers;
  if (!scenarios.empty())
    for (const DriverRun& run : scenarios.front().runs) drivers.push_back(run.driver);
  if (drivers.empty()) drivers = {"signalsim", "sumo"};
  std::string out = padded("scenario", 28) + padded("section", 18) + padded("id", 6) + padded("blinker", 7);
  for (std::size_t d = 0; d < drivers.size(); ++d) out += d + 1 < drivers.size() ? padded(drivers[d], 28) : drivers[d] + "\n";
  std::size_t lines = 0, items = 0;
  bool off_plan = false;
  for (std::size_t i = 0; i < rows.size();) {
    // The rows of one item: consecutive rows with the same scenario and section.
    std::size_t j = i;
    std::vector<std::string> cells(drivers.size());
    while (j < rows.size() && rows[j][column("scenario")] == rows[i][column("scenario")] &&
           rows[j][column("section")] == rows[i][column("section")]) {
      const std::string text = screen_cell(rows[j]);
      off_plan = off_plan || text.ends_with(" *");
      const auto at = std::find(drivers.begin(), drivers.end(), rows[j][column("driver")]);
      if (at != drivers.end()) cells[static_cast<std::size_t>(at - drivers.begin())] = text;
      ++j;
    }
    ++items;
    if (lines < max_lines) {
      const Row& r = rows[i];
      out += padded(r[column("scenario")], 28) + padded(r[column("section")].empty() ? "-" : r[column("section")], 18) +
             padded(r[column("id")], 6) + padded(r[column("blinker")].empty() ? "-" : r[column("blinker")], 7);
      for (std::size_t d = 0; d < cells.size(); ++d) out += d + 1 < cells.size() ? padded(cells[d], 28) : cells[d] + "\n";
      ++lines;
    }
    i = j;
  }
  if (items > lines) out += "... " + std::to_string(items - lines) + " more in comparison.csv\n";
  if (off_plan) out += "* SUMO drove off the planned lanes there (comparison.csv notes)\n";
  std::size_t errors = 0;
  for (const ScenarioComparison& sc : scenarios)
    for (const DriverRun& run : sc.runs)
      if (run.status == "error" && errors++ < 5) out += "error: " + sc.scenario + " (" + run.driver + "): " + run.error + "\n";
  return out;
}

}  // namespace signalsim
