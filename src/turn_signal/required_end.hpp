// Required end point of a turn lane from its geometry (docs/behaviour.md §T7, the code's backward scan).
#pragma once

#include "core/polyline.hpp"

namespace signalsim {

/// Arc length along `centerline` of the required end point for an angle threshold in degrees:
/// resample every 1 m (the last sample merged with the end when closer than 0.1 m) with an Akima
/// spline in x and y, recompute the yaws, then scan from the last pose backward and return the first
/// pose whose |yaw - yaw_end| >= threshold; the lane end when there is none. 0 for < 2 points.
double required_end_arc_length(const Polyline& centerline, double angle_threshold_deg);

}  // namespace signalsim
