#include "twin/roads/iso8608.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/toml_reader.hpp"
#include "twin/scenario.hpp"

namespace dtwin {

std::shared_ptr<const RoadSetting> IsoRoadSetting::parse(TableReader& rr) {
  auto rs = std::make_shared<IsoRoadSetting>();
  const std::string cls = rr.string("class").value_or("D");
  if (cls.size() != 1 || cls[0] < 'A' || cls[0] > 'H')
    throw InputError(rr.where("class"), "must be one of A..H, got '" + cls + "'");
  rs->iso_class = cls[0];
  rs->smooth_until_s = rr.number("smooth_until_s", rs->smooth_until_s);
  if (!std::isfinite(rs->smooth_until_s) || rs->smooth_until_s < 0)
    throw InputError(rr.where("smooth_until_s"), "must be >= 0 s (0: rough from the start), got " +
                                                     formatNumber(rs->smooth_until_s));
  if (auto* band = rr.array("band_cycles_per_m")) {
    if (band->size() != 2 || !band->get(0)->value<double>() || !band->get(1)->value<double>())
      throw InputError(rr.where("band_cycles_per_m"), "must be two numbers [n_min, n_max]");
    rs->n_min = *band->get(0)->value<double>();
    rs->n_max = *band->get(1)->value<double>();
    if (!(rs->n_min > 0 && rs->n_max > rs->n_min))
      throw InputError(rr.where("band_cycles_per_m"), "needs 0 < n_min < n_max");
  }
  rs->dx_m = rr.positive("dx_m", 0.01);
  if (rs->dx_m < 1e-4)
    throw InputError(
        rr.where("dx_m"),
        "must be at least 1e-4 m (docs/study-file.md, Limits), got " + formatNumber(rs->dx_m));
  if (rs->n_max >= 0.25 / rs->dx_m)
    throw InputError(rr.where("dx_m"),
                     "must give >= 4 points per shortest wavelength (dx < 0.25/n_max)");
  rs->taper_m = rr.positive("taper_m", 1.0);
  const std::string tracks = rr.string("tracks").value_or("independent");
  if (tracks == "independent")
    rs->coherence = IsoRoadSpec::Coherence::Independent;
  else if (tracks == "identical")
    rs->coherence = IsoRoadSpec::Coherence::Identical;
  else
    throw InputError(rr.where("tracks"),
                     "must be \"independent\" or \"identical\", got \"" + tracks + "\"");
  return rs;
}

void IsoRoadSetting::check(const ScenarioSpec& s, const std::string& where) const {
  // The grid covers the distance travelled plus margins (make() below); at most 1e7 points a track.
  const double points = (s.speed.distance(s.duration_s) + 20.0) / dx_m;
  if (points > 1e7)
    throw InputError(where + ".dx_m",
                     "gives " + formatNumber(points, 3) + " grid points over the " +
                         formatNumber(s.speed.distance(s.duration_s), 4) +
                         " m the scenario travels; at most 1e7 (docs/study-file.md, Limits)");
}

nlohmann::json IsoRoadSetting::toJson() const {
  return {{"type", "iso8608"},
          {"class", std::string(1, iso_class)},
          {"smooth_until_s", smooth_until_s},
          {"band_cycles_per_m", {n_min, n_max}},
          {"dx_m", dx_m},
          {"taper_m", taper_m},
          {"tracks", coherence == IsoRoadSpec::Coherence::Identical ? "identical" : "independent"}};
}

std::shared_ptr<const Road> IsoRoadSetting::make(const ScenarioSpec& s, const VehicleData& v,
                                                 std::uint64_t seed) const {
  const double x_end = s.speed.distance(s.duration_s) + 5.0;  // front axle, plus margin
  const double x_begin = -v.wheelbase() - 5.0;                // rear axle at t = 0, minus margin
  IsoRoadSpec iso;
  iso.road_class = iso_class;
  iso.n_min = n_min;
  iso.n_max = n_max;
  iso.dx_m = dx_m;
  iso.x_begin_m = x_begin;
  iso.length_m = x_end - x_begin;
  iso.smooth_until_m = smooth_until_s > 0 ? s.speed.distance(smooth_until_s) : -1e300;
  iso.taper_m = taper_m;
  iso.coherence = coherence;
  iso.seed = seed;
  return makeIsoRoad(iso);
}

std::vector<std::string> IsoRoadSetting::describeWindow(const ScenarioSpec&, const VehicleData&,
                                                        double t0, double t1) const {
  std::vector<std::string> parts;
  if (t0 < smooth_until_s) parts.push_back("smooth road before the rough section");
  if (t1 >= smooth_until_s)
    parts.push_back("rough road (ISO 8608 class " + std::string(1, iso_class) + ")");
  return parts;
}

}  // namespace dtwin
