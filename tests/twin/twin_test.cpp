// Full-vehicle checks of the Simbody twin: static equilibrium, per-run parameters without
// rebuilds, effects, and the regression traces in data/reference/.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numeric>
#include <sstream>

#include "io/study.hpp"
#include "shipped_study.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& paper() { return dtwin_test::shippedStudy("paper"); }

double maxOf(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

using dtwin_test::standstill;
}  // namespace

TEST(Twin, AssembliesAreTheCartesianProductInStudyOrder) {
  const auto a = paper().assemblies();
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].label(), "pac2002 + macpherson");
  EXPECT_EQ(a[1].label(), "pac2002 + solid_axle");
  EXPECT_EQ(a[2].label(), "fiala + macpherson");
  EXPECT_EQ(a[3].label(), "fiala + solid_axle");
}

TEST(Twin, StaticEquilibriumHubForcesCarryTheWeightInCgProportion) {
  for (const auto& a : paper().assemblies()) {
    SCOPED_TRACE(a.id);
    auto model = paper().makeModel(a);
    Simulator sim(model, paper().simulation);
    FlatRoad road;
    const auto r = sim.run(model->defaultRunValues(), road, standstill(2.0));
    ASSERT_TRUE(r.stats.ok) << r.stats.message;
    const auto& v = model->vehicle();
    const double weight = v.total_mass(model->topology()) * v.gravity;
    // Corner shares from the CG position, computed here independently of the model code.
    const double m_unsprung_axle =
        2 * v.wheel_mass + (model->topology() == SuspensionTopology::SolidAxle ? v.axle_mass : 0.0);
    const double front_axle = (v.chassis_mass * v.b / v.wheelbase() + m_unsprung_axle) * v.gravity;
    const double expected[4] = {front_axle / 2, front_axle / 2, (weight - front_axle) / 2,
                                (weight - front_axle) / 2};
    for (std::size_t row : {std::size_t(0), r.trace.rows() - 1}) {
      double sum = 0;
      for (int c = 0; c < 4; ++c) {
        const double f = r.trace.column(std::string("hub_force_") + kCornerNames[c] + "_N")[row];
        sum += f;
        EXPECT_NEAR(f, expected[c], 0.005 * expected[c])
            << "corner " << kCornerNames[c] << " row " << row;
      }
      EXPECT_NEAR(sum, weight, 0.005 * weight) << "row " << row;
    }
    // A true equilibrium does not move.
    EXPECT_LT(std::abs(r.trace.column("chassis_heave_m").back()), 1e-5);
    EXPECT_LT(std::abs(r.trace.column("susp_defl_fl_m").back()), 1e-5);
  }
}

TEST(Twin, OneSystemRunsManyParameterSetsReproducibly) {
  const auto& a = paper().assembly("M1");
  auto model = paper().makeModel(a);
  Simulator sim(model, paper().simulation);
  const auto& sc = paper().scenario("lab");
  auto road = makeRoad(sc, model->vehicle(), 1);
  auto v1 = model->defaultRunValues();
  auto v2 = v1;
  v2[static_cast<std::size_t>(model->slot("tire.stiffness"))] = 300e3;
  const auto r1 = sim.run(v1, *road, sc);
  const auto r2 = sim.run(v2, *road, sc);
  const auto r1b = sim.run(v1, *road, sc);
  const double p1 = maxOf(r1.trace.column("hub_force_fl_N")),
               p2 = maxOf(r2.trace.column("hub_force_fl_N"));
  EXPECT_GT(std::abs(p2 - p1), 0.02 * p1) << "a stiffer tire must change the bump peak";
  EXPECT_EQ(r1.trace.column("hub_force_fl_N"), r1b.trace.column("hub_force_fl_N"))
      << "no state may leak between runs";
}

TEST(Twin, BumpIsMetByTheFrontWheelsAtSixSeconds) {
  auto model = paper().makeModel(paper().assembly("M3"));
  Simulator sim(model, paper().simulation);
  const auto& sc = paper().scenario("lab");
  auto road = makeRoad(sc, model->vehicle(), 1);
  const auto r = sim.run(model->defaultRunValues(), *road, sc);
  const auto& t = r.trace.column("time_s");
  const auto& h = r.trace.column("road_fl_m");
  const auto& hr = r.trace.column("road_rl_m");
  auto first_nonzero = [&](const std::vector<double>& c) {
    for (std::size_t i = 0; i < c.size(); ++i)
      if (c[i] > 1e-9) return t[i];
    return -1.0;
  };
  EXPECT_NEAR(first_nonzero(h), 6.0, 1.5e-3);
  EXPECT_NEAR(first_nonzero(hr), 6.0 + model->vehicle().wheelbase() / 8.9408, 1.5e-3);
  // 1 kHz samples straddle the 11 ms crossing: the crest can fall up to 0.5 ms between samples.
  EXPECT_NEAR(maxOf(h), 0.2, 5e-3);
  EXPECT_GT(maxOf(h), 0.19);
}

TEST(Twin, EffectsAtTheirOffValuesChangeNothingAndSwitchedOnTheyDo) {
  const auto& a = paper().assembly("M1");
  const auto& sc = paper().scenario("lab");
  auto base = paper().makeModel(a);
  auto road = makeRoad(sc, base->vehicle(), 1);
  Simulator sim0(base, paper().simulation);
  const auto r0 = sim0.run(base->defaultRunValues(), *road, sc);
  const double peak0 = maxOf(r0.trace.column("hub_force_fl_N"));
  struct Case {
    std::string effect;
    std::vector<ParameterSetting> on;
    std::string channel;
  };
  const std::vector<Case> cases = {
      {"bump_stop",
       {{"bump_stop.stiffness", 5e6, "", "test"}, {"bump_stop.gap_m", 0.02, "", "test"}},
       "susp_defl_fl_m"},
      {"damper_asymmetry", {{"damper_asymmetry.ratio", 3.0, "", "test"}}, "susp_defl_fl_m"},
      {"strut_friction", {{"strut_friction.force_N", 400.0, "", "test"}}, "susp_defl_fl_m"},
      {"tire_enveloping", {{"tire_enveloping.length_m", 0.3, "", "test"}}, "hub_force_fl_N"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.effect);
    auto off = paper().makeModel(a, {EffectSetting{c.effect, {}}});
    Simulator s_off(off, paper().simulation);
    const auto r_off = s_off.run(off->defaultRunValues(), *road, sc);
    const auto& f0 = r0.trace.column("hub_force_fl_N");
    const auto& f1 = r_off.trace.column("hub_force_fl_N");
    ASSERT_EQ(f0.size(), f1.size());
    double dmax = 0;
    for (std::size_t i = 0; i < f0.size(); ++i) dmax = std::max(dmax, std::abs(f0[i] - f1[i]));
    EXPECT_LT(dmax, 1e-6 * peak0) << "an effect at its off values must not change the trace";

    auto on = paper().makeModel(a, {EffectSetting{c.effect, c.on}});
    Simulator s_on(on, paper().simulation);
    const auto r_on = s_on.run(on->defaultRunValues(), *road, sc);
    ASSERT_TRUE(r_on.stats.ok) << r_on.stats.message;
    const auto& x0 = r0.trace.column(c.channel);
    const auto& x1 = r_on.trace.column(c.channel);
    double diff = 0, scale = 0;
    for (std::size_t i = 0; i < x0.size(); ++i) {
      diff = std::max(diff, std::abs(x0[i] - x1[i]));
      scale = std::max(scale, std::abs(x0[i]));
    }
    EXPECT_GT(diff, 0.02 * scale) << "switched on, " << c.effect << " must visibly change "
                                  << c.channel;
  }
}

TEST(Twin, EnvelopingLowersTheBumpPeak) {
  const auto& a = paper().assembly("M1");
  const auto& sc = paper().scenario("lab");
  auto base = paper().makeModel(a);
  auto env = paper().makeModel(
      a, {EffectSetting{"tire_enveloping", {{"tire_enveloping.length_m", 0.3, "", "test"}}}});
  auto road = makeRoad(sc, base->vehicle(), 1);
  Simulator s0(base, paper().simulation), s1(env, paper().simulation);
  const double p0 =
      maxOf(s0.run(base->defaultRunValues(), *road, sc).trace.column("hub_force_fl_N"));
  const double p1 =
      maxOf(s1.run(env->defaultRunValues(), *road, sc).trace.column("hub_force_fl_N"));
  EXPECT_LT(p1, 0.8 * p0);
}

// ---------------------------------------------------------------- reference traces
namespace {
std::vector<std::vector<double>> readCsv(const std::string& path,
                                         std::vector<std::string>& header) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::string line;
  std::getline(in, line);
  std::stringstream hs(line);
  std::string cell;
  while (std::getline(hs, cell, ',')) header.push_back(cell);
  std::vector<std::vector<double>> cols(header.size());
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    for (std::size_t c = 0; c < header.size() && std::getline(ss, cell, ','); ++c)
      cols[c].push_back(std::stod(cell));
  }
  return cols;
}
}  // namespace

class ReferenceTrace : public ::testing::TestWithParam<std::string> {};

// Tolerance (stated in data/reference/README.md): hub forces within 1 % of the reference peak,
// displacements within 0.5 mm, angles within 0.5 mrad, at every stored sample.
TEST_P(ReferenceTrace, BumpResponseMatchesStoredReference) {
  const std::string id = GetParam();
  std::vector<std::string> header;
  const auto ref =
      readCsv(std::string(DTWIN_SOURCE_DIR) + "/data/reference/" + id + "_lab.csv", header);
  ASSERT_GT(ref.at(0).size(), 1000u);
  auto model = paper().makeModel(paper().assembly(id));
  Simulator sim(model, paper().simulation);
  const auto& sc = paper().scenario("lab");
  auto road = makeRoad(sc, model->vehicle(), paper().seed);
  const auto r = sim.run(model->defaultRunValues(), *road, sc);
  const auto& t = r.trace.column("time_s");
  const double rate = sim.options().output_rate_hz;
  double peak = 0;
  for (std::size_t c = 1; c < header.size(); ++c)
    if (header[c].find("_N") != std::string::npos) peak = std::max(peak, maxOf(ref[c]));
  for (std::size_t c = 1; c < header.size(); ++c) {
    const auto& now = r.trace.column(header[c]);
    // 0.5 mm and 0.5 mrad are the same number in SI units.
    const double tol = header[c].find("_N") != std::string::npos ? 0.01 * peak : 5e-4;
    double worst = 0;
    for (std::size_t i = 0; i < ref[0].size(); ++i) {
      const auto row = static_cast<std::size_t>(std::llround(ref[0][i] * rate));
      ASSERT_NEAR(t[row], ref[0][i], 1e-9);
      worst = std::max(worst, std::abs(now[row] - ref[c][i]));
    }
    EXPECT_LE(worst, tol) << id << " channel " << header[c];
  }
}
INSTANTIATE_TEST_SUITE_P(Assemblies, ReferenceTrace, ::testing::Values("M1", "M2", "M3", "M4"));
