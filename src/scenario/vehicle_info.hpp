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

  double length() const { return front_overhang + wheel_base + rear_overhang; }
  double width() const { return wheel_tread + left_overhang + right_overhang; }
  double base_link_to_front() const { return wheel_base + front_overhang; }
};

/// Reads a vehicle_info file. Throws InputError naming the file and line: missing file, malformed
/// YAML, a missing or non-numeric dimension, a negative one (a zero wheel base or tread), a key one
/// edit away from a known one ("did you mean"), and when `strict` a key that is not one of
/// Autoware's vehicle_info keys (wheel_radius, wheel_width, vehicle_height, max_steer_angle are
/// known but unused: listed in `unused`).
VehicleInfo load_vehicle_info(const std::string& path, bool strict = false);

}  // namespace signalsim
