#include "common/format.hpp"

#include <sstream>

namespace dtwin {

std::string formatNumber(double v, int digits) {
  std::ostringstream os;
  os.precision(digits);
  os << v;
  return os.str();
}

}  // namespace dtwin
