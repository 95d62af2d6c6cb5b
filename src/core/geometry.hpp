// Plain 2-D value types and angle helpers shared by every layer.
#pragma once

#include <cmath>
#include <numbers>

namespace signalsim {

struct Vec2 {
  double x = 0.0;  ///< metres, SUMO's net coordinates
  double y = 0.0;  ///< metres

  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
  friend bool operator==(Vec2 a, Vec2 b) = default;
};

inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
inline double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double norm(Vec2 a) { return std::hypot(a.x, a.y); }
inline double distance(Vec2 a, Vec2 b) { return norm(b - a); }

/// A position with a heading (yaw, radians, counter-clockwise from +x).
struct Pose {
  Vec2 position;
  double yaw = 0.0;
};

/// Wraps an angle into (-pi, pi].
double normalize_angle(double radians);

inline double deg_to_rad(double degrees) { return degrees * std::numbers::pi / 180.0; }
inline double rad_to_deg(double radians) { return radians * 180.0 / std::numbers::pi; }

/// Azimuth of the vector from a to b.
inline double azimuth(Vec2 a, Vec2 b) { return std::atan2(b.y - a.y, b.x - a.x); }

}  // namespace signalsim
