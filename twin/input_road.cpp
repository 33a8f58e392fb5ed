#include "twin/input_road.hpp"

#include <algorithm>
#include <limits>

#include "common/errors.hpp"

namespace dtwin {

const InputRoad::Profile& InputRoad::at(int corner) const {
  DTWIN_CHECK(corner >= 0 && corner < 4, "InputRoad: corner out of range");
  return p_[static_cast<std::size_t>(corner)];
}

double InputRoad::lastSlope(const Profile& p) {
  const std::size_t n = p.x.size();
  if (n < 2) return 0.0;
  return (p.h[n - 1] - p.h[n - 2]) / (p.x[n - 1] - p.x[n - 2]);
}

void InputRoad::push(int corner, double x, double h) {
  (void)at(corner);
  Profile& p = p_[static_cast<std::size_t>(corner)];
  if (!p.x.empty() && !(x > p.x.back() + 1e-9)) {  // standing: the height under the wheel
    p.h.back() = h;
    const std::size_t n = p.x.size();
    if (n >= 2) p.cum[n - 1] = p.cum[n - 2] + 0.5 * (p.h[n - 2] + h) * (p.x[n - 1] - p.x[n - 2]);
    return;
  }
  const double cum = p.x.empty() ? 0.0 : p.cum.back() + 0.5 * (p.h.back() + h) * (x - p.x.back());
  p.x.push_back(x);
  p.h.push_back(h);
  p.cum.push_back(cum);
}

RoadSample InputRoad::sampleAt(int corner, double x) const {
  const Profile& p = at(corner);
  const std::size_t n = p.x.size();
  if (n == 0) return {};
  if (x <= p.x.front()) return {p.h.front(), 0.0};
  if (x >= p.x.back()) {
    const double m = lastSlope(p);
    return {p.h.back() + m * (x - p.x.back()), m};
  }
  // Mostly near the end (the wheels read where the last samples are): search from there.
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(p.x.begin(), p.x.end(), x) - p.x.begin()) - 1;
  const double m = (p.h[k + 1] - p.h[k]) / (p.x[k + 1] - p.x[k]);
  return {p.h[k] + m * (x - p.x[k]), m};
}

double InputRoad::integralAt(int corner, double x) const {
  const Profile& p = at(corner);
  const std::size_t n = p.x.size();
  if (n == 0) return 0.0;
  if (x <= p.x.front()) return p.h.front() * (x - p.x.front());
  if (x >= p.x.back()) {
    const double d = x - p.x.back();
    return p.cum.back() + p.h.back() * d + 0.5 * lastSlope(p) * d * d;
  }
  const std::size_t k =
      static_cast<std::size_t>(std::upper_bound(p.x.begin(), p.x.end(), x) - p.x.begin()) - 1;
  const double d = x - p.x[k], m = (p.h[k + 1] - p.h[k]) / (p.x[k + 1] - p.x[k]);
  return p.cum[k] + p.h[k] * d + 0.5 * m * d * d;
}

Interval InputRoad::extent() const {
  constexpr double kHuge = std::numeric_limits<double>::max();
  return {-kHuge, kHuge};  // held before the first sample, continued after the last
}

nlohmann::json InputRoad::describe() const {
  return {{"type", "input"},
          {"rule",
           "the height under each wheel from a co-simulation's inputs, piecewise linear in the "
           "wheel's road distance, continued along the last slope"}};
}

}  // namespace dtwin
