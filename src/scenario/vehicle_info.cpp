// Reading Autoware's vehicle_info.param.yaml.
#include "scenario/vehicle_info.hpp"

#include <cmath>

#include <yaml-cpp/yaml.h>

#include "scenario/autoware_key_table.hpp"
#include "scenario/input_error.hpp"
#include "scenario/parameter_keys.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {

// The dimensions signalsim uses (Autoware's file has more keys, read by other nodes:
// data/autoware_keys.yaml lists them).
constexpr const char* kUsed[] = {"wheel_base", "front_overhang", "rear_overhang",
                                 "wheel_tread", "left_overhang", "right_overhang"};
constexpr const char* kAutowareFile = "vehicle_info.param.yaml";  // its keys in the table, whatever the name
constexpr double kMaxDimension = 30.0;  // [m] as ego.length's upper bound

}  // namespace

VehicleInfo load_vehicle_info(const std::string& path, bool strict) {
  const std::vector<FlatParameter> flat = document_parameters(load_shared_yaml_file(path, "vehicle_info file"), path);
  VehicleInfo info;
  info.file = path;
  std::map<std::string, double*> fields = {
      {"wheel_base", &info.wheel_base},   {"front_overhang", &info.front_overhang},
      {"rear_overhang", &info.rear_overhang}, {"wheel_tread", &info.wheel_tread},
      {"left_overhang", &info.left_overhang}, {"right_overhang", &info.right_overhang}};
  for (const FlatParameter& entry : flat) {
    if (info.lines.count(entry.name))
      throw InputError(path, entry.line, "'" + entry.name + "' is given twice (also at line " +
                                             std::to_string(info.lines.at(entry.name)) + ")");
    const auto field = fields.find(entry.name);
    if (field == fields.end()) {
      for (const char* name : kUsed)
        if (edit_distance(entry.name, name) <= 1)
          throw InputError(path, entry.line, "unknown key '" + entry.name + "' (did you mean '" + name + "'?)");
      if (const auto warning = strict ? strict_key_warning(autoware_key_tables(), kAutowareFile, path, entry.line,
                                                           entry.name, "key")
                                      : std::nullopt)
        info.warnings.push_back(*warning);
      else
        info.unused.push_back(entry.name);
      continue;
    }
    std::string reason = "expected a number, got '" + entry.value.Scalar() + "'";  // a quoted one
    const std::optional<double> number = entry.value.Tag() == "!" ? std::nullopt : yaml_number(entry.value, reason);
    if (!number) throw InputError(path, entry.line, "'" + entry.name + "': " + reason);
    const double value = *number;
    const bool must_be_positive = entry.name == "wheel_base" || entry.name == "wheel_tread";
    if (value < 0.0 || (must_be_positive && value <= 0.0) || value > kMaxDimension)
      throw InputError(path, entry.line, "'" + entry.name + "': " + entry.value.Scalar() + " m is out of range " +
                                             (must_be_positive ? "(0, 30]" : "[0, 30]"));
    *field->second = value;
    info.lines[entry.name] = entry.line;
  }
  for (const char* name : kUsed)
    if (!info.lines.count(name)) throw InputError(path, 0, std::string("missing key '") + name + "'");
  return info;
}

}  // namespace signalsim
