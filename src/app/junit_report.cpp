// The JUnit cases of check and batch: classname, file, properties, pictures (see junit_report.hpp).
#include "app/junit_report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/plot_tool.hpp"
#include "batch/run_outputs.hpp"
#include "report/atomic_file.hpp"
#include "report/run_files.hpp"
#include "scenario/input_error.hpp"

namespace signalsim::app {
namespace fs = std::filesystem;
namespace {

std::string text_of(const nlohmann::ordered_json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

// The scenario file's folder relative to the working directory with dots for slashes, then the net's
// file stem ("scenarios.cross"); either alone when the other is empty.
std::string classname_of(const std::string& scenario_file, const std::string& net) {
  const fs::path folder = fs::path(path_for_ci(scenario_file)).parent_path();
  std::string name;
  for (const fs::path& part : folder) {
    const std::string text = part.string();
    if (text.empty() || text == "/" || text == ".") continue;
    name += (name.empty() ? "" : ".") + text;
  }
  std::string net_stem = fs::path(net).filename().string();
  if (const auto dot = net_stem.find('.'); dot != std::string::npos && dot > 0) net_stem.erase(dot);  // x.net.xml
  if (!net_stem.empty()) name += (name.empty() ? "" : ".") + net_stem;
  return name;
}

// The parameter files the run's values came from ("<file>:<line>" origins), in first-seen order.
std::vector<std::string> parameter_files(const nlohmann::ordered_json& summary) {
  std::vector<std::string> files;
  if (!summary.contains("parameter_sources") || !summary["parameter_sources"].is_object()) return files;
  for (const auto& [name, source] : summary["parameter_sources"].items()) {
    const std::string from = text_of(source, "from");
    const auto colon = from.rfind(':');
    if (colon == std::string::npos || colon == 0 || from.find_first_not_of("0123456789", colon + 1) != std::string::npos)
      continue;  // default, "country jp", "set", "--set"
    const std::string file = from.substr(0, colon);
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  }
  return files;
}

std::vector<std::pair<std::string, std::string>> properties_of(const nlohmann::ordered_json& summary) {
  std::vector<std::pair<std::string, std::string>> out;
  if (summary.contains("seed") && summary["seed"].is_number_integer())
    out.emplace_back("seed", std::to_string(summary["seed"].get<long long>()));
  out.emplace_back("country", text_of(summary, "country"));
  out.emplace_back("net", text_of(summary, "net"));
  for (const std::string& file : parameter_files(summary)) out.emplace_back("parameter_file", file);
  for (const char* role : {"decider", "light_judge"}) {
    const std::string name = summary.contains(role) ? text_of(summary[role], "name") : std::string();
    out.emplace_back(role, name.empty() ? "reference" : name);
  }
  return out;
}

bool is_png(const fs::path& path) { return path.extension() == ".png"; }

std::vector<std::string> pngs_in(const fs::path& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file(ec) && is_png(entry.path())) out.push_back(entry.path().string());
  std::sort(out.begin(), out.end());  // the directory's order is the file system's
  return out;
}

}  // namespace

std::string path_for_ci(const std::string& path) {
  std::error_code ec;
  const fs::path here = fs::current_path(ec);
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  if (ec) return path;
  const fs::path relative = absolute.lexically_relative(here);
  const bool inside = !relative.empty() && *relative.begin() != "..";
  return inside ? relative.string() : absolute.string();
}

std::string failures_of(const nlohmann::ordered_json& summary) {
  std::string out;
  if (summary.contains("expectations") && summary["expectations"].is_array())
    for (const auto& e : summary["expectations"])
      if (!e.value("passed", true))
        out += "expectation failed: " + e.value("expectation", std::string("?")) + ": " +
               e.value("detail", std::string()) + "\n";
  if (summary.contains("law") && summary["law"].is_object())
    for (const auto& v : summary["law"].value("verdicts", nlohmann::ordered_json::array()))
      if (!v.value("passed", true))
        out += "law verdict failed: " + v.value("section", std::string()) + " " + v.value("id", std::string()) +
               " " + v.value("rule", std::string()) + ": " + v.value("detail", std::string()) + "\n";
  return out;
}

JUnitCase junit_case(const RunSpec& run, const nlohmann::ordered_json& summary) {
  JUnitCase c;
  c.name = fs::path(run.scenario).stem().string();
  c.file = path_for_ci(run.scenario);
  c.classname = classname_of(run.scenario, text_of(summary, "net"));
  if (summary.is_object()) c.properties = properties_of(summary);
  return c;
}

nlohmann::ordered_json summary_or_null(const std::string& run_dir) {
  try {
    return read_json_file((fs::path(run_dir) / run_files::kSummary).string());
  } catch (const std::exception&) {
    return nullptr;
  }
}

void attach_pictures(JUnitCase& c, const std::string& run_dir) {
  if (c.result != JUnitCase::Result::Failed && c.result != JUnitCase::Result::Error) return;
  std::error_code ec;
  if (!fs::exists(fs::path(run_dir) / run_files::kSummary, ec)) return;
  const fs::path plots = fs::path(run_dir) / "plots";
  // a run that ended before its timeline (SUMO did not load, a bad route) has nothing to draw
  const bool drawable = fs::is_regular_file(fs::path(run_dir) / run_files::kTimeline, ec);
  if (drawable && pngs_in(plots).empty()) run_plot_tool({run_dir, "--quiet"});  // a failure is reported; the case stands
  std::vector<std::string> pictures = pngs_in(plots);
  if (const fs::path gui = fs::path(run_dir) / run_files::kGuiScreenshot; fs::is_regular_file(gui, ec))
    pictures.push_back(gui.string());
  for (const std::string& picture : pictures) c.attachments.push_back(path_for_ci(picture));
}

std::vector<JUnitCase> batch_junit_cases(const std::vector<RunSpec>& runs, const ResultRows& rows,
                                         const std::string& out_dir) {
  std::vector<JUnitCase> cases;
  for (const RunSpec& run : runs) {
    const auto it = rows.find(run.index);
    const std::string run_dir =
        it == rows.end() ? std::string() : (fs::path(out_dir) / row_cell(it->second, "run_dir")).string();
    const nlohmann::ordered_json summary = run_dir.empty() ? nlohmann::ordered_json() : summary_or_null(run_dir);
    JUnitCase c = junit_case(run, summary);
    if (it == rows.end()) {
      c.result = JUnitCase::Result::Error;
      c.message = "the run did not finish";
    } else {
      const ResultRow& row = it->second;
      c.time = std::atof(row_cell(row, "wall_time").c_str());
      const std::string status = row_cell(row, "status");
      if (summary.is_object()) c.system_out = failures_of(summary);
      if (status == "error") {
        c.result = JUnitCase::Result::Error;
        c.message = "run error: " + row_cell(row, "error");
      } else if (status == "failed") {
        c.result = JUnitCase::Result::Failed;
        const std::string expectations = row_cell(row, "failed_expectations"), law = row_cell(row, "law_failed");
        const std::string law_part = !law.empty() && law != "0" ? "law verdicts failed: " + law : "";
        c.message = expectations.empty() ? law_part
                                         : "expectations failed: " + expectations + (law_part.empty() ? "" : "; " + law_part);
      } else if (status == "no_expectations") {
        c.result = JUnitCase::Result::Skipped;
        c.message = "the scenario has no expectations: nothing was checked";
      }
      attach_pictures(c, run_dir);
    }
    cases.push_back(std::move(c));
  }
  return cases;
}

void check_writable_folder(const std::string& dir, const std::string& flag) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir, ec))
    throw InputError(flag, 0, "cannot create the folder '" + dir + "'" + (ec ? ": " + ec.message() : std::string()));
  const fs::path probe = fs::path(dir) / (".signalsim-check-" + std::to_string(getpid()));
  const bool written = static_cast<bool>(std::ofstream(probe) << "");
  fs::remove(probe, ec);
  if (!written) throw InputError(flag, 0, "cannot write into the folder '" + dir + "'");
}

void check_junit_destination(const std::string& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw InputError("--junit", 0, "'" + file + "' is a folder, not a file");
  const fs::path parent = fs::path(file).parent_path();
  check_writable_folder(parent.empty() ? "." : parent.string(), "--junit");
}

void write_junit(const std::string& file, const std::string& suite, const std::vector<JUnitCase>& cases, double wall) {
  if (const fs::path parent = fs::path(file).parent_path(); !parent.empty()) fs::create_directories(parent);
  write_file_atomically(file, junit_xml(suite, cases, wall));
}

}  // namespace signalsim::app
