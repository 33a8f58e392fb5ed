#pragma once
// Axis ticks a reader takes in at a glance, for the gnuplot figures of the reports: steps of 1, 2,
// 2.5 or 5 times a power of ten, labelled "150k" rather than "1.5397e+05" (report/study_report.cpp,
// report/diagnosis_report.cpp).
//
//   niceTicks(0.0, 153970.0)        -> {0, 20000, 40000, ..., 140000}  (about six ticks)
//   tickLabel(150000.0, 20000.0)    -> "150k"
//   tickLabel(-3.5e6, 5e5)          -> "-3.5M"
//   tickLabel(0.0125, 0.0025)       -> "0.0125"
//   gnuplotTics("x", 0.0, 153970.0) -> "set xrange [0:153970]\nset xtics (\"0\" 0, \"20k\" 20000,
//   ...)\n"
#include <string>
#include <vector>

namespace dtwin::report {

/// The step 1, 2, 2.5 or 5 × 10^k closest above (hi − lo) / target, and the multiples of it in
/// [lo, hi] (within a millionth of a step of either end). lo == hi gives {lo}; non-finite or
/// lo > hi gives {}.
std::vector<double> niceTicks(double lo, double hi, int target = 6);

/// The tick step of niceTicks(lo, hi, target) (0 when lo == hi or the input is not finite).
double niceStep(double lo, double hi, int target = 6);

/// `v` as a tick label for ticks `step` apart: the fewest decimals that tell neighbouring ticks
/// apart, with the SI suffix k (from 10 000), M (from 10⁶), G or T chosen by the magnitude (the
/// largest of |v|, the step and `magnitude`: pass the axis's largest |tick| so that one axis has
/// one suffix): "150k", "2.5M"; magnitudes below 0.001 in scientific form ("2e-05"). Never "-0".
std::string tickLabel(double v, double step, double magnitude = 0.0);

/// gnuplot commands setting `axis` ("x", "y", "x2"...) to the range [lo, hi] with niceTicks of
/// it, labelled by tickLabel (or with empty labels when !labelled: the inner panels of a grid).
/// An empty or degenerate range is widened by a thousandth of its magnitude (or 1 at zero) first.
std::string gnuplotTics(const std::string& axis, double lo, double hi, int target = 6,
                        bool labelled = true);

/// [lo, hi] widened by `fraction` of its span on each side (a margin for points at the edges);
/// a zero span is widened by `fraction` of the magnitude (or of 1 at zero).
void padRange(double& lo, double& hi, double fraction = 0.04);

/// "name [unit]" (just `name` when the unit is empty or "1").
std::string axisLabel(const std::string& name, const std::string& unit);

}  // namespace dtwin::report
