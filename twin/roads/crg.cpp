#include "twin/roads/crg.hpp"

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/toml_reader.hpp"
#include "twin/scenario.hpp"

namespace dtwin {

std::shared_ptr<const RoadSetting> CrgRoadSetting::parse(TableReader& rr) {
  auto rs = std::make_shared<CrgRoadSetting>();
  auto p = rr.string("path");
  if (!p) throw InputError(rr.where("path"), "is required for a crg road (an OpenCRG file)");
  rs->path = rr.resolvePath(*p);
  rs->left_v_m = rr.number("left_v_m");
  rs->right_v_m = rr.number("right_v_m");
  rs->u_start_m = rr.number("u_start_m");
  rs->surface = std::make_shared<const CrgSurface>(readCrg(rs->path));
  const CrgSurface& s = *rs->surface;
  if (rs->left_v_m && rs->right_v_m && !(*rs->left_v_m > *rs->right_v_m))
    throw InputError(rr.where("left_v_m"), "must be greater than right_v_m (v points left), got " +
                                               formatNumber(*rs->left_v_m) +
                                               " <= " + formatNumber(*rs->right_v_m));
  for (const char* k : {"left_v_m", "right_v_m"}) {
    const auto& v = std::string(k) == "left_v_m" ? rs->left_v_m : rs->right_v_m;
    if (v && (*v < s.v_m.front() - 1e-9 || *v > s.v_m.back() + 1e-9))
      throw InputError(rr.where(k), "v = " + formatNumber(*v) +
                                        " lies outside the long sections of " + rs->path + " (v " +
                                        formatNumber(s.v_m.front()) + " .. " +
                                        formatNumber(s.v_m.back()) + ")");
  }
  if (rs->u_start_m && (*rs->u_start_m < s.u0_m || *rs->u_start_m > s.u1_m()))
    throw InputError(rr.where("u_start_m"),
                     "u = " + formatNumber(*rs->u_start_m) + " lies outside " + rs->path + " (u " +
                         formatNumber(s.u0_m) + " .. " + formatNumber(s.u1_m()) + ")");
  return rs;
}

nlohmann::json CrgRoadSetting::toJson() const {
  nlohmann::json j = {{"type", "crg"}, {"path", path}};
  if (left_v_m) j["left_v_m"] = *left_v_m;
  if (right_v_m) j["right_v_m"] = *right_v_m;
  if (u_start_m) j["u_start_m"] = *u_start_m;
  return j;
}

double CrgRoadSetting::frontU(const ScenarioSpec& s, double t) const {
  return uStart() + s.speed.distance(t) - s.speed.distance(0.0);
}

std::shared_ptr<const Road> CrgRoadSetting::make(const ScenarioSpec& s, const VehicleData& v,
                                                 std::uint64_t) const {
  const CrgSurface& c = *surface;
  const double left = left_v_m.value_or(0.5 * v.track), right = right_v_m.value_or(-0.5 * v.track);
  // The default tracks (half the track width each side) must lie on the file too.
  for (double tv : {left, right})
    if (tv < c.v_m.front() - 1e-9 || tv > c.v_m.back() + 1e-9)
      throw InputError(path, "a wheel track at v = " + formatNumber(tv) +
                                 " lies outside the long sections (v " +
                                 formatNumber(c.v_m.front()) + " .. " + formatNumber(c.v_m.back()) +
                                 "); set left_v_m and right_v_m in the road table");
  const double u_end = frontU(s, s.duration_s);
  if (u_end > c.u1_m() + 1e-9)
    throw InputError(path, "the front axle drives from u = " + formatNumber(uStart()) + " to " +
                               formatNumber(u_end) + " in scenario '" + s.name +
                               "', past the file's last cross section at u = " +
                               formatNumber(c.u1_m()) + " (shorten the run or lower u_start_m)");
  nlohmann::json d = {{"type", "crg"},
                      {"path", path},
                      {"format", c.format},
                      {"rows", c.rows},
                      {"du_m", c.du_m},
                      {"u_range_m", {c.u0_m, c.u1_m()}},
                      {"v_range_m", {c.v_m.front(), c.v_m.back()}},
                      {"long_sections", c.v_m.size()},
                      {"left_v_m", left},
                      {"right_v_m", right},
                      {"u_start_m", uStart()},
                      {"z_offset_m", c.z_offset_m},
                      {"nan_filled", c.nan_filled + c.nan_inside},
                      {"banked", !c.bank.empty()}};
  if (c.plan_geometry)
    d["plan_geometry"] = "curved or placed reference line: the twin drives along u, straight";
  // Road distance x = u - (u_start - start_m): the front axle is at u_start at time 0.
  return makeCrgRoad(c, left, right, uStart() - s.speed.distance(0.0), std::move(d));
}

std::vector<std::string> CrgRoadSetting::describeWindow(const ScenarioSpec& s, const VehicleData&,
                                                        double t0, double t1) const {
  return {"OpenCRG road surface, front axle over u = " + formatNumber(frontU(s, t0)) + " .. " +
          formatNumber(frontU(s, t1)) + " m"};
}

}  // namespace dtwin
