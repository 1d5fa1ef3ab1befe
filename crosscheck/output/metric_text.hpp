// How a metric's value is spelled, the same in every output (text, JUnit, the HTML report, the
// bench table): PSNR as "%.2f" or "inf" when the images are identical; a depth value or
// threshold as its shortest float spelling when it is a float (2^-24 is "5.9604645e-08", as the
// scene files write it), else with 9 significant digits; and the names used around them: "|Δ|"
// for an absolute difference, "allowed" for a limit on a count, "threshold" for a limit on a
// difference. Deliberately only spelling: which metrics an output shows is the output's business.
#pragma once

#include <string>

namespace crosscheck {

inline constexpr const char* kAbsDelta = "|\xCE\x94|";  // |Δ| in UTF-8

std::string psnrText(double psnr);
std::string depthText(double depth);

}  // namespace crosscheck
