// Autoware's vehicle description (vehicle_info.param.yaml, `/**: ros__parameters:`) as the ego's
// footprint: base_link is the rear axle's centre, so
//   length             = front_overhang + wheel_base + rear_overhang
//   width              = wheel_tread + left_overhang + right_overhang
//   base_link_to_front = wheel_base + front_overhang
#pragma once

#include <map>
#include <string>
#include <vector>

namespace signalsim {

struct VehicleInfo {
  std::string file;
  double wheel_base = 0.0, front_overhang = 0.0, rear_overhang = 0.0;  ///< [m]
  double wheel_tread = 0.0, left_overhang = 0.0, right_overhang = 0.0;  ///< [m]
  std::map<std::string, int> lines;  ///< the file's line of each key read
  std::vector<std::string> unused;   ///< keys of the file signalsim does not use
  std::vector<std::string> warnings;  ///< strict: one line per key Autoware dropped

  double length() const { return front_overhang + wheel_base + rear_overhang; }
  double width() const { return wheel_tread + left_overhang + right_overhang; }
  double base_link_to_front() const { return wheel_base + front_overhang; }
};

/// Reads a vehicle_info file. Throws InputError naming the file and line: missing file, malformed
/// YAML, a missing or non-numeric dimension, a negative one (a zero wheel base or tread), a key one
/// edit away from a used one ("did you mean"), and when `strict` a key Autoware's vehicle_info
/// does not have either (scenario/autoware_key_table.hpp). Keys signalsim does not use are listed in
/// `unused` (wheel_radius, wheel_width, vehicle_height, max_steer_angle), keys Autoware dropped in
/// `warnings` (strict).
VehicleInfo load_vehicle_info(const std::string& path, bool strict = false);

}  // namespace signalsim
