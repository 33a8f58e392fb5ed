#pragma once
// A road fed from outside the twin, sample by sample: the height under each wheel as a
// co-simulation's inputs give it (twin/stepped_run.hpp). Each corner keeps its own profile against
// its road distance (the front wheels' is the distance travelled, the rear wheels' that less the
// wheelbase, as on every road), piecewise linear between the samples received, and continued
// past the last sample along the last two samples' slope (a first-order hold that predicts the
// step ahead). Before the first sample the first height is held.
#include <array>
#include <vector>

#include "subsystems/road.hpp"

namespace dtwin {

class InputRoad final : public Road {
 public:
  /// Adds corner `corner`'s height `h` [m] at its road distance `x` [m]. A distance not beyond the
  /// corner's last (the car stands) replaces the last sample's height.
  void push(int corner, double x, double h);
  /// The samples a corner holds.
  std::size_t size(int corner) const { return at(corner).x.size(); }

  RoadSample sample(Track t, double x) const override { return sampleAt(trackCorner(t), x); }
  double integral(Track t, double x) const override { return integralAt(trackCorner(t), x); }
  RoadSample sampleAt(int corner, double x) const override;
  double integralAt(int corner, double x) const override;
  Interval extent() const override;
  nlohmann::json describe() const override;

 private:
  struct Profile {
    std::vector<double> x, h, cum;  ///< distances, heights, integral from x[0] at each sample
  };
  static int trackCorner(Track t) { return t == Track::Left ? 0 : 1; }
  const Profile& at(int corner) const;
  /// The last segment's slope (0 with fewer than two samples).
  static double lastSlope(const Profile& p);
  std::array<Profile, 4> p_;
};

}  // namespace dtwin
