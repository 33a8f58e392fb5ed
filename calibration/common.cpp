#include "calibration/common.hpp"

#include <cmath>
#include <sstream>

#include "common/errors.hpp"

namespace dtwin::calib {

void sequentialFor(int count, const std::function<void(int)>& task) {
  for (int i = 0; i < count; ++i) task(i);
}

void checkBounds(const std::vector<double>& lower, const std::vector<double>& upper,
                 const std::string& where, bool allow_degenerate) {
  if (lower.empty()) throw InputError(where, "bounds must have at least one parameter, got 0");
  if (lower.size() != upper.size()) {
    std::ostringstream os;
    os << "lower and upper bounds must have the same size, got " << lower.size() << " and "
       << upper.size();
    throw InputError(where, os.str());
  }
  for (std::size_t j = 0; j < lower.size(); ++j) {
    const bool ok = std::isfinite(lower[j]) && std::isfinite(upper[j]) &&
                    (allow_degenerate ? lower[j] <= upper[j] : lower[j] < upper[j]);
    if (!ok) {
      std::ostringstream os;
      os.precision(17);
      os << "bounds of parameter " << j << " must be finite with lower "
         << (allow_degenerate ? "<=" : "<") << " upper, got [" << lower[j] << ", " << upper[j]
         << "]";
      throw InputError(where, os.str());
    }
  }
}

}  // namespace dtwin::calib
