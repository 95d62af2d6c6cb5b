// The end of a turn lanelet's required section as autoware_core's path_generator finds it
// (planning/autoware_path_generator/src/utils.cpp, get_turn_signal_required_end_point, commit
// 2d693b82): the first centerline point whose heading is within the angle threshold of the
// lanelet's terminal heading. Pure geometry on the lanelet's centerline; no state.
#pragma once

#include <optional>
#include <vector>

namespace signalsim::autoware_core {

struct Point2 {
  double x = 0.0, y = 0.0;
};

/// Arc length [m] along `centerline` (its polyline length) of the required end point, or nullopt
/// where path_generator's returns nullopt (fewer than 4 points even after its resampling).
std::optional<double> required_end_arc(const std::vector<Point2>& centerline, double angle_threshold_deg);

/// Length [m] of the polyline.
double polyline_length(const std::vector<Point2>& points);

}  // namespace signalsim::autoware_core
