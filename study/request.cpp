#include "study/request.hpp"

#include "common/errors.hpp"

namespace dtwin {

void applyTimeWindow(const std::vector<double>& window, double& begin_s, double& end_s) {
  if (window.empty()) return;
  if (window.size() != 2 || !(window[0] < window[1]))
    throw InputError("--window", "expects T0,T1 with T0 < T1");
  begin_s = window[0];
  end_s = window[1];
}

}  // namespace dtwin
