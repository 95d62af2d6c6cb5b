// judge_curves.csv of a run (see judge_curves.hpp).
#include "report/judge_curves.hpp"

#include <cmath>

#include "core/number_text.hpp"
#include "traffic_light/judge_line.hpp"

namespace signalsim {

std::string judge_curves_csv(const TrafficLightJudgeParameters& p) {
  std::string out = "speed,judge_distance,yellow_lamp_line\n";
  const int steps = static_cast<int>(std::lround(kJudgeCurveTopSpeed / kJudgeCurveSpeedStep));
  for (int k = 0; k <= steps; ++k) {
    const double v = k * kJudgeCurveSpeedStep;
    const double judge = calc_judge_line_dist_with_jerk_limit(v, 0.0, p.max_accel, p.max_jerk, p.delay_response_time);
    out += format_text("%.3f,%.3f,%.3f\n", v, judge, v * p.yellow_lamp_period);
  }
  return out;
}

}  // namespace signalsim
