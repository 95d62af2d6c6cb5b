// The exit codes of every signalsim command, and how a batch reads its workers' (docs/batch.md).
// 0 success, 1 an expectation (or regression) failed, 2 bad input; sweep --plot and compare: 3 the
// picture failed; batch, sweep and check: 4 a run errored (no verdict); 130 interrupted, `run`: 143 on
// SIGTERM.
#pragma once

namespace signalsim {

inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitPicture = 3;        ///< sweep --plot, compare: the runs were fine, the picture failed
inline constexpr int kExitRunErrors = 4;      ///< batch, sweep, check: a run errored (no verdict; wins over 1)
inline constexpr int kExitInterrupted = 130;  ///< SIGINT (batch, sweep, check, compare: also SIGTERM)
inline constexpr int kExitTerminated = 143;   ///< `run` stopped by SIGTERM (128 + 15)

}  // namespace signalsim
