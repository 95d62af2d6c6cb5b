// Numbers as the output files write them: fixed-point text with a given number of decimals, the
// text printf's "%.*f" gives, written with std::to_chars (the timeline writes about 14 numbers a
// step, and printf's format parsing was a third of an ego-only step's instructions).
#pragma once

#include <string>

namespace signalsim {

/// `v` with `decimals` decimals exactly as printf("%.*f", decimals, v) writes it (correctly rounded
/// from the binary value, ties to even; "nan", "-nan", "inf", "-inf"; a negative `decimals` means 6),
/// except that "-0.0", "-0.00" and "-0.000" lose their sign: a value that rounds to zero is written
/// the same on every platform and run.
std::string fixed(double v, int decimals);

/// The same text appended to `out`, without a temporary string.
void append_fixed(std::string& out, double v, int decimals);

/// `v` in decimal, appended to `out` (std::to_string's text).
void append_integer(std::string& out, long long v);

}  // namespace signalsim
