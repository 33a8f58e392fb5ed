#pragma once
// Road profiles h(x) [m] along the travelled distance x [m], one per wheel track.
// The vehicle is kept in place and the road moves under it: the contact point of a wheel whose
// hub sits at ground x-coordinate x_h is at road distance s(t) + x_h (docs/model.md).
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dtwin {

enum class Track : int { Left = 0, Right = 1 };

/// The track of a corner: 0 front left, 1 front right, 2 rear left, 3 rear right (twin/model.hpp's
/// Corner).
inline Track cornerTrack(int corner) { return corner % 2 == 0 ? Track::Left : Track::Right; }

struct RoadSample {
  double height_m = 0.0;
  double slope = 0.0;  ///< dh/dx [m/m]
};

struct Interval {
  double lo = 0.0, hi = 0.0;
};

class Road {
 public:
  virtual ~Road() = default;
  virtual RoadSample sample(Track t, double x) const = 0;
  /// Antiderivative of h for track t (any fixed origin); used for moving averages.
  virtual double integral(Track t, double x) const = 0;
  /// The road under corner `corner` (0 FL, 1 FR, 2 RL, 3 RR) at the wheel's road distance x (a
  /// rear wheel's is the front's less the wheelbase). Every wheel reads its track's profile
  /// (sample(cornerTrack(corner), x)) but on a four-corner road (CornerRoad), where each reads its
  /// own.
  virtual RoadSample sampleAt(int corner, double x) const { return sample(cornerTrack(corner), x); }
  /// The antiderivative under corner `corner` (integral(cornerTrack(corner), x) but on a
  /// four-corner road).
  virtual double integralAt(int corner, double x) const { return integral(cornerTrack(corner), x); }
  /// True on a four-corner road (CornerRoad): each wheel's profile is that wheel's own motion,
  /// the rear ones already at their own times, so a road-signal form reads a rear wheel's without
  /// the wheelbase's read-ahead (twin/road_contact.hpp, RunContext::signalAt).
  virtual bool eachWheelOwn() const { return false; }
  /// Mean height over [x - L/2, x + L/2] and its derivative with respect to x.
  RoadSample sampleAveraged(Track t, double x, double L) const;
  /// Range of x over which the profile is defined (outside it, the end value is held).
  virtual Interval extent() const = 0;
  /// Short obstacles (x ranges) near which the integrator's step must be bounded.
  virtual std::vector<Interval> obstacles() const { return {}; }
  /// How the road was made (type, parameters, seed, ...), for provenance sidecars.
  virtual nlohmann::json describe() const = 0;
};

class FlatRoad final : public Road {
 public:
  RoadSample sample(Track, double) const override { return {}; }
  double integral(Track, double) const override { return 0.0; }
  Interval extent() const override;
  nlohmann::json describe() const override { return {{"type", "flat"}}; }
};

/// One-cosine speed bump across both tracks: h = H/2 (1 - cos(2 pi (x - x0)/L)) on [x0, x0 + L].
class BumpRoad final : public Road {
 public:
  BumpRoad(double start_x_m, double height_m, double length_m);
  RoadSample sample(Track t, double x) const override;
  double integral(Track t, double x) const override;
  Interval extent() const override;
  std::vector<Interval> obstacles() const override { return {{x0_, x0_ + L_}}; }
  nlohmann::json describe() const override;

 private:
  double x0_, H_, L_;
};

/// A profile sampled on a uniform grid, interpolated with C1 cubic Hermite (Catmull-Rom)
/// splines; integrals are exact for that interpolant.
class GridRoad final : public Road {
 public:
  /// Slopes at the nodes: `left_slope`/`right_slope` when given (the same length as the
  /// heights: a profile whose slopes are known better than its heights' central differences),
  /// else the central differences.
  GridRoad(double x0_m, double dx_m, std::vector<double> left_m, std::vector<double> right_m,
           nlohmann::json description, std::vector<double> left_slope = {},
           std::vector<double> right_slope = {});
  RoadSample sample(Track t, double x) const override;
  double integral(Track t, double x) const override;
  Interval extent() const override;
  nlohmann::json describe() const override { return description_; }
  double x0() const { return x0_; }
  double dx() const { return dx_; }
  const std::vector<double>& heights(Track t) const { return h_[static_cast<int>(t)]; }

 private:
  double x0_, dx_;
  std::vector<double> h_[2], m_[2], prefix_[2];  // heights, slopes at nodes, integral at nodes
  nlohmann::json description_;
};

/// A road whose four wheels each read their own profile (a log of each wheel's motion,
/// subsystems/time_road.hpp): the front wheels the tracks of `front`, the rear wheels those of
/// `rear`, each at its own road distance x (a rear wheel's is the front's less the wheelbase, as
/// on every road: `rear` is laid out on that distance). sample(Track, x) and integral(Track, x)
/// read the front wheel of that side; extent() and obstacles() are both roads'.
class CornerRoad final : public Road {
 public:
  CornerRoad(std::shared_ptr<const Road> front, std::shared_ptr<const Road> rear,
             nlohmann::json description);
  RoadSample sample(Track t, double x) const override { return front_->sample(t, x); }
  double integral(Track t, double x) const override { return front_->integral(t, x); }
  RoadSample sampleAt(int corner, double x) const override {
    return (corner < 2 ? front_ : rear_)->sample(cornerTrack(corner), x);
  }
  double integralAt(int corner, double x) const override {
    return (corner < 2 ? front_ : rear_)->integral(cornerTrack(corner), x);
  }
  Interval extent() const override;
  std::vector<Interval> obstacles() const override;
  nlohmann::json describe() const override { return description_; }
  bool eachWheelOwn() const override { return true; }
  const Road& front() const { return *front_; }
  const Road& rear() const { return *rear_; }

 private:
  std::shared_ptr<const Road> front_, rear_;
  nlohmann::json description_;
};

/// One corner of a road seen as a road whose both tracks are that corner's (sample(t, x) is
/// road.sampleAt(corner, x), integral likewise): what a tire-input effect (Effect::filterRoad,
/// which reads a track) is given, so that on a four-corner road it reads its wheel's own profile.
/// Holds a reference: lives no longer than the road.
class CornerView final : public Road {
 public:
  CornerView(const Road& road, int corner) : road_(road), corner_(corner) {}
  RoadSample sample(Track, double x) const override { return road_.sampleAt(corner_, x); }
  double integral(Track, double x) const override { return road_.integralAt(corner_, x); }
  Interval extent() const override { return road_.extent(); }
  std::vector<Interval> obstacles() const override { return road_.obstacles(); }
  nlohmann::json describe() const override { return road_.describe(); }

 private:
  const Road& road_;
  int corner_;
};

/// ISO 8608 random road (docs/method.md §2): Gd(n) = Gd(n0) (n/n0)^-w, n0 = 0.1 cycles/m, w = 2 by
/// default. Made as a sum of cosines on the frequency grid k/P (P the period) with random
/// phases, evaluated by inverse FFT. Each bin's amplitude is sqrt(2 * integral of Gd over the
/// bin within the band), so the profile's mean square over a period equals the integral of Gd
/// over the band exactly; the band edges are stated in every description.
struct IsoRoadSpec {
  char road_class = 'D';           ///< A..H (geometric mean of the class)
  double n_min = 0.011;            ///< lowest spatial frequency kept [cycles/m]
  double n_max = 2.83;             ///< highest [cycles/m]
  double waviness = 2.0;           ///< w
  double dx_m = 0.01;              ///< grid spacing
  double x_begin_m = 0.0;          ///< first grid point
  double length_m = 200.0;         ///< covered length
  double smooth_until_m = -1e300;  ///< flat before this x, raised-cosine taper after it
  double taper_m = 1.0;            ///< taper length
  enum class Coherence { Independent, Identical } coherence = Coherence::Independent;
  unsigned long long seed = 1;
};

/// Gd(n0) [m^3] of an ISO 8608 class (geometric mean): A 16e-6, B 64e-6, ..., H 262144e-6.
double isoClassGd0(char road_class);
/// RMS height over the band for w = 2: sqrt(Gd(n0) n0^2 (1/n_min - 1/n_max)) (the integral of Gd(n)
/// over the band).
double isoRmsHeight(char road_class, double n_min, double n_max);
std::shared_ptr<const GridRoad> makeIsoRoad(const IsoRoadSpec& spec);

/// Reads a CSV with header "distance_m,left_m,right_m", uniform spacing, strictly increasing
/// distance, finite values. Errors name the file and line (InputError).
std::shared_ptr<const GridRoad> loadRoadCsv(const std::string& path);

}  // namespace dtwin
