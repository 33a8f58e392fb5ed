// Per-corner and per-axle factors ("suspension.damping@rr", twin/parameters.hpp; docs/model.md,
// "Per-corner and per-axle values"): at 1 they are the base model bit for bit, an axle's factor is
// its two corners' factors, one corner's tire stiffness warps the static equilibrium as the closed
// form says, and bad names and values are one-line input errors naming the field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>

#include "io/study.hpp"
#include "shipped_study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {

const Study& paperStudy() { return dtwin_test::shippedStudy("paper"); }

RunResult runOn(const std::shared_ptr<const Model>& model, const ScenarioSpec& sc) {
  Simulator sim(model, paperStudy().simulation);
  const auto road = makeRoad(sc, model->vehicle(), 1);
  RunResult r = sim.run(model->defaultRunValues(), *road, sc);
  EXPECT_TRUE(r.stats.ok) << r.stats.message;
  return r;
}

/// Every channel of `a` and `b` equal, bit for bit.
void expectSameTrace(const Trace& a, const Trace& b) {
  ASSERT_EQ(a.channels().size(), b.channels().size());
  ASSERT_EQ(a.rows(), b.rows());
  for (std::size_t i = 0; i < a.channels().size(); ++i)
    EXPECT_EQ(a.column(i), b.column(i)) << "channel " << a.channels()[i].name;
}

std::vector<ParameterSetting> settings(const std::vector<std::pair<std::string, double>>& values) {
  std::vector<ParameterSetting> out;
  for (const auto& v : values) out.push_back({v.first, v.second, "test: " + v.first, "test"});
  return out;
}

/// The message of the InputError `f` throws ("" if none).
template <class F>
std::string inputError(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(CornerFactors, DeclaredInTheTableAtOneWithUnitAndPrior) {
  const ParameterTable t = paperStudy().parameterTable();
  for (const char* name : {"suspension.stiffness@fl", "suspension.damping@rr",
                           "tire.stiffness@front", "tire.damping@rear"}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(t.contains(name));
    const auto& e = t.at(name);
    EXPECT_EQ(e.value, 1.0);
    EXPECT_EQ(e.spec.unit, "1");
    EXPECT_FALSE(e.spec.description.empty());
    EXPECT_EQ(e.spec.prior_lower, 0.2);
    EXPECT_EQ(e.spec.prior_upper, 2.0);
  }
  EXPECT_EQ(cornerFactorNames().size(), 24u);
  // Not run parameters unless freed, calibrated or set away from 1.
  const auto base = paperStudy().makeModel(paperStudy().assembly("M1"));
  for (const auto& n : cornerFactorNames()) EXPECT_LT(base->slot(n), 0) << n;
  for (int c = 0; c < 4; ++c) {
    EXPECT_TRUE(base->strutFactors()[static_cast<std::size_t>(c)].empty());
    EXPECT_TRUE(base->tireFactors()[static_cast<std::size_t>(c)].empty());
  }
  const auto set = paperStudy().makeModel(paperStudy().assembly("M1"), {},
                                          settings({{"suspension.damping@rr", 0.5}}));
  EXPECT_GE(set->slot("suspension.damping@rr"), 0);
  EXPECT_EQ(set->strutFactors()[3].size(), 1u);
  EXPECT_TRUE(set->strutFactors()[2].empty());
}

TEST(CornerFactors, CalibratedFactorsAreRunParametersAtOne) {
  Study s = paperStudy();
  s.calibrated.push_back({"suspension.damping@rr", "1", 0.2, 2.0, std::nullopt});
  s.calibrated.push_back({"tire.stiffness@front", "1", 0.2, 2.0, std::nullopt});
  for (const char* id : {"M1", "M2"}) {
    const auto m = s.makeModel(s.assembly(id));
    EXPECT_GE(m->slot("suspension.damping@rr"), 0) << id;
    EXPECT_GE(m->slot("tire.stiffness@front"), 0) << id;
    EXPECT_EQ(m->defaultRunValues()[static_cast<std::size_t>(m->slot("suspension.damping@rr"))],
              1.0);
    EXPECT_EQ(m->tireFactors()[0].size(), 1u);
    EXPECT_EQ(m->tireFactors()[2].size(), 0u);
  }
}

// Every factor a run parameter at 1: each law value is multiplied by 1.0 at every corner, which
// is exact, so the bump trace is the base model's bit for bit (every channel).
TEST(CornerFactors, AllFactorsAtOneGiveTheBaseTraceBitForBit) {
  const auto& sc = paperStudy().scenario("lab");
  for (const char* id : {"M1", "M2", "M3", "M4"}) {
    SCOPED_TRACE(id);
    AssemblySpec a = paperStudy().assembly(id);
    const auto base = paperStudy().makeModel(a);
    a.freed = cornerFactorNames();
    const auto factored = paperStudy().makeModel(a);
    for (const auto& n : cornerFactorNames()) ASSERT_GE(factored->slot(n), 0) << n;
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(factored->strutFactors()[static_cast<std::size_t>(c)].size(),
                4u);  // stiffness, damping: axle and corner
      EXPECT_EQ(factored->tireFactors()[static_cast<std::size_t>(c)].size(), 4u);
    }
    expectSameTrace(runOn(base, sc).trace, runOn(factored, sc).trace);
  }
}

// value x factor(axle) x factor(corner): an axle's factor f is its two corners' factors f, bit for
// bit.
TEST(CornerFactors, AnAxleFactorIsBothItsCornersFactors) {
  const auto& sc = paperStudy().scenario("lab");
  for (const char* id : {"M1", "M2"}) {
    SCOPED_TRACE(id);
    const AssemblySpec a = paperStudy().assembly(id);
    const auto axle = paperStudy().makeModel(
        a, {}, settings({{"tire.damping@front", 0.7}, {"suspension.stiffness@rear", 1.3}}));
    const auto corners = paperStudy().makeModel(a, {},
                                                settings({{"tire.damping@fl", 0.7},
                                                          {"tire.damping@fr", 0.7},
                                                          {"suspension.stiffness@rl", 1.3},
                                                          {"suspension.stiffness@rr", 1.3}}));
    const auto base = runOn(paperStudy().makeModel(a), sc);
    const auto ra = runOn(axle, sc), rc = runOn(corners, sc);
    expectSameTrace(ra.trace, rc.trace);
    EXPECT_NE(ra.trace.column("hub_force_fl_N"), base.trace.column("hub_force_fl_N"))
        << "the factors must act";
  }
}

// The fiala + MacPherson assembly at rest with the front left tire twice as stiff. Four corners on
// a rigid body are statically indeterminate by one warp mode w = (+1, -1, -1, +1) (fl, fr, rl, rr):
// loads W_c + w_c d. The corners' total compressions delta_c = load_c / k_c + w_c d / k_s (tire in
// series with the strut; the strut's preload carries the static load at q = 0) must keep the four
// body corners coplanar, sum_c w_c delta_c = 0, so
//   d = -sum_c w_c W_c / k_c / sum_c (1 / k_c + 1 / k_s) = (W_f / (2k)) / (3.5 / k + 4 / k_s).
// The stiffer corner takes load, its diagonal partner too; the other two give it up.
TEST(CornerFactors, OneStifferTireWarpsTheStaticLoadsAsTheClosedFormSays) {
  const AssemblySpec a = paperStudy().assembly("M3");
  ASSERT_EQ(a.label(), "fiala + macpherson");
  const auto sc = dtwin_test::standstill(20.0);
  const auto base_model = paperStudy().makeModel(a);
  const auto model = paperStudy().makeModel(a, {}, settings({{"tire.stiffness@fl", 2.0}}));
  const auto base = runOn(base_model, sc), r = runOn(model, sc);
  const double k = model->table().value("tire.stiffness"),
               ks = model->table().value("suspension.stiffness");
  const double Wf = model->staticTireLoad(0), Wr = model->staticTireLoad(2);
  const double d = (Wf / (2 * k)) / (3.5 / k + 4 / ks);
  auto last = [](const RunResult& x, const std::string& ch) { return x.trace.column(ch).back(); };
  const double F[4] = {last(r, "hub_force_fl_N"), last(r, "hub_force_fr_N"),
                       last(r, "hub_force_rl_N"), last(r, "hub_force_rr_N")};
  const double warp = (F[0] - F[1] - F[2] + F[3]) / 4;
  EXPECT_NEAR(warp, d, 0.005 * d) << "the closed form's warp load";
  // Tire deflections: load / stiffness, the front left's at 2k.
  const double rho_fl = last(r, "tire_defl_fl_m"), rho_fr = last(r, "tire_defl_fr_m");
  const double rho_diff = (Wf + d) / (2 * k) - (Wf - d) / k;
  EXPECT_LT(rho_fl, rho_fr);
  EXPECT_NEAR(rho_fl - rho_fr, rho_diff, 0.005 * std::abs(rho_diff));
  // Strut compressions: +-d / k_s (the warp mode only).
  const double q_warp = (last(r, "susp_defl_fl_m") - last(r, "susp_defl_fr_m") -
                         last(r, "susp_defl_rl_m") + last(r, "susp_defl_rr_m")) /
                        4;
  EXPECT_NEAR(q_warp, d / ks, 0.005 * d / ks);
  // The rear pair's symmetric part is unchanged: the warp takes from one rear wheel what it gives
  // the other.
  const double rear = (last(r, "tire_defl_rl_m") + last(r, "tire_defl_rr_m")) / 2;
  const double rear_base = (last(base, "tire_defl_rl_m") + last(base, "tire_defl_rr_m")) / 2;
  EXPECT_NEAR(rear, rear_base, 1e-3 * rear_base);
  EXPECT_NEAR(rear_base, Wr / k, 1e-3 * Wr / k);
  // The start is that equilibrium already (the simulator solves the warp with the laws; without
  // it the rear right hub started 1782 N off): the hub forces move by a few newtons over the run,
  // the lever arms of the rolled and pitched body, which the warp's closed form leaves out.
  for (const char* ch : {"hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N", "hub_force_rr_N"}) {
    const auto& col = r.trace.column(ch);
    double most = 0;
    for (double v : col) most = std::max(most, std::abs(v - col.back()));
    EXPECT_LT(most, 0.1 * d) << ch;
    std::printf("%s: start %.4f N, end %.4f N, largest move %.4f N\n", ch, col.front(), col.back(),
                most);
  }
  // The base run is symmetric left to right, bit for bit up to the equilibrium's solution.
  EXPECT_NEAR(last(base, "hub_force_fl_N"), last(base, "hub_force_fr_N"), 1e-6 * Wf);
  std::printf(
      "closed form d = %.4f N, model warp %.4f N (%.3g %%); rho_fl - rho_fr = %.6e m, closed form "
      "%.6e m\n",
      d, warp, 100 * (warp - d) / d, rho_fl - rho_fr, rho_diff);
}

// The solid axle: a strut factor is the axle's spring at that side's seat. A softer rear-left
// spring breaks the left/right symmetry of the bump run.
TEST(CornerFactors, OneCornersSpringBreaksTheSymmetryOnTheSolidAxle) {
  const AssemblySpec a = paperStudy().assembly("M2");
  const auto& sc = paperStudy().scenario("lab");
  const auto base = runOn(paperStudy().makeModel(a), sc);
  const auto r =
      runOn(paperStudy().makeModel(a, {}, settings({{"suspension.stiffness@rl", 0.5}})), sc);
  double base_gap = 0, gap = 0;
  const auto &bl = base.trace.column("hub_force_rl_N"), &br = base.trace.column("hub_force_rr_N");
  const auto &l = r.trace.column("hub_force_rl_N"), &rr = r.trace.column("hub_force_rr_N");
  for (std::size_t i = 0; i < l.size(); ++i) {
    base_gap = std::max(base_gap, std::abs(bl[i] - br[i]));
    gap = std::max(gap, std::abs(l[i] - rr[i]));
  }
  EXPECT_LT(base_gap, 1.0);
  EXPECT_GT(gap, 50.0);
}

// The solid axle (fiala): a stiffer front left tire takes load from its neighbour on the axle,
// the rear pair's mean is kept, the settled warp is the closed form's, and the run starts in it.
TEST(CornerFactors, OnTheSolidAxleOneStifferTireWarpsAsTheClosedFormSays) {
  const AssemblySpec a = paperStudy().assembly("M4");
  ASSERT_EQ(a.label(), "fiala + solid_axle");
  const auto r = runOn(paperStudy().makeModel(a, {}, settings({{"tire.stiffness@fl", 2.0}})),
                       dtwin_test::standstill(20.0));
  const auto base = runOn(paperStudy().makeModel(a), dtwin_test::standstill(20.0));
  auto last = [](const RunResult& x, const std::string& ch) { return x.trace.column(ch).back(); };
  const double Ffl = last(r, "hub_force_fl_N"), Ffr = last(r, "hub_force_fr_N");
  EXPECT_GT(Ffl, Ffr);
  EXPECT_LT(last(r, "tire_defl_fl_m"), last(r, "tire_defl_fr_m"));
  const double rear = last(r, "tire_defl_rl_m") + last(r, "tire_defl_rr_m"),
               rear_base = last(base, "tire_defl_rl_m") + last(base, "tire_defl_rr_m");
  EXPECT_NEAR(rear, rear_base, 1e-3 * rear_base);
  // The warp's closed form on a solid axle: the seats (spring_track s apart) carry the wheels'
  // (track t apart) roll moment, seat forces +-d t/s; the axle's roll carries the wheels'
  // differences to the seats scaled by s/t, the wheel/axle interfaces (k_wa) in series with the
  // tires:
  //   d = (s/t) (W_f / 2k) / ((s/t) (3.5/k + 4/k_wa) + 4 (t/s) / k_s).
  const auto model = paperStudy().makeModel(a);
  const Model& m = *model;
  const double k = m.table().value("tire.stiffness"), ks = m.table().value("suspension.stiffness");
  const double kwa = m.table().value("suspension.solid_axle.interface_stiffness");
  const double st = m.vehicle().spring_track / m.vehicle().track, Wf = m.staticTireLoad(0);
  const double d = st * (Wf / (2 * k)) / (st * (3.5 / k + 4 / kwa) + 4 / (st * ks));
  const double warp = (Ffl - Ffr - last(r, "hub_force_rl_N") + last(r, "hub_force_rr_N")) / 4;
  EXPECT_NEAR(warp, d, 1e-3 * d);
  for (const char* ch : {"hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N", "hub_force_rr_N"}) {
    const auto& col = r.trace.column(ch);
    double most = 0;
    for (double v : col) most = std::max(most, std::abs(v - col.back()));
    EXPECT_LT(most, 0.2 * d) << ch << ": the start is the warped equilibrium";
  }
  std::printf("solid axle: closed form d = %.4f N, model warp %.4f N (%.3g %%)\n", d, warp,
              100 * (warp - d) / d);
  std::printf(
      "solid axle: hub forces fl %.2f N, fr %.2f N, rl %.2f N, rr %.2f N; start fl %.2f N, rr %.2f "
      "N\n",
      Ffl, Ffr, last(r, "hub_force_rl_N"), last(r, "hub_force_rr_N"),
      r.trace.column("hub_force_fl_N").front(), r.trace.column("hub_force_rr_N").front());
}

TEST(CornerFactors, BadNamesAndValuesAreOneLineInputErrors) {
  const Study& s = paperStudy();
  const AssemblySpec a = s.assembly("M1");
  auto with = [&](const std::string& name, double v) {
    return inputError([&] { s.makeModel(a, {}, settings({{name, v}})); });
  };
  for (double v : {0.0, -0.5}) {
    const std::string m = with("suspension.damping@rr", v);
    EXPECT_NE(m.find("suspension.damping@rr must be > 0"), std::string::npos) << m;
  }
  std::string m = with("suspension.damping@xx", 0.5);
  EXPECT_NE(
      m.find("'suspension.damping@xx': unknown place 'xx' (places: fl, fr, rl, rr, front, rear)"),
      std::string::npos)
      << m;
  m = with("chassis.mass_kg@fl", 0.5);
  EXPECT_NE(m.find("'chassis.mass_kg@fl': chassis.mass_kg has no per-corner or per-axle factor"),
            std::string::npos)
      << m;
  for (const auto& msg : {m, with("suspension.damping@xx", 0.5)})
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  // Freed (a calibration, a diagnosis): the same rules.
  AssemblySpec bad = a;
  bad.freed = {"tire.damping@middle"};
  m = inputError([&] { s.makeModel(bad); });
  EXPECT_NE(m.find("unknown place 'middle'"), std::string::npos) << m;
  // A tire option without tire compliance has no tire stiffness to scale.
  AssemblySpec hub = a;
  for (auto& o : hub.options)
    if (o.first == "tire") o.second = "hub";
  m = inputError([&] { s.makeModel(hub, {}, settings({{"tire.stiffness@fl", 2.0}})); });
  EXPECT_NE(m.find("'tire.stiffness@fl': assembly M1"), std::string::npos) << m;
  EXPECT_NE(m.find("has no tire.stiffness"), std::string::npos) << m;
  // A study file's [[calibrated]] name.
  namespace fs = std::filesystem;
  const fs::path dir = dtwin_test::freshDir("corner_factor_study");
  std::string text =
      dtwin_test::slurp(fs::path(DTWIN_SOURCE_DIR) / "data" / "studies" / "paper.toml");
  text = std::regex_replace(
      text, std::regex("vehicle = \"[^\"]*\""),
      "vehicle = \"" +
          (fs::path(DTWIN_SOURCE_DIR) / "data" / "vehicle" / "midsize_sedan.toml").string() + "\"");
  const auto at = text.find("[scenarios.lab]");
  ASSERT_NE(at, std::string::npos);
  const std::string entry =
      "[[calibrated]]\nname = \"tire.damping@xx\"\nunit = \"1\"\nlower = 0.2\nupper = 2.0\n\n";
  dtwin_test::writeText(dir / "bad.toml", text.substr(0, at) + entry + text.substr(at));
  m = inputError([&] { loadStudy((dir / "bad.toml").string()); });
  EXPECT_NE(m.find("calibrated[4].name: 'tire.damping@xx': unknown place 'xx'"), std::string::npos)
      << m;
  const std::string good =
      "[[calibrated]]\nname = \"tire.damping@rr\"\nunit = \"1\"\nlower = 0.2\nupper = 2.0\n\n";
  dtwin_test::writeText(dir / "good.toml", text.substr(0, at) + good + text.substr(at));
  const Study g = loadStudy((dir / "good.toml").string());
  EXPECT_GE(g.makeModel(g.assembly("M3"))->slot("tire.damping@rr"), 0);
}

// The command line: --set with a factor runs; a bad one is one line naming it, exit code 2.
TEST(CornerFactors, SetOnTheCommandLine) {
  const auto dir = dtwin_test::freshDir("corner_factor_cli");
  const std::string study = std::string(DTWIN_SOURCE_DIR) + "/data/studies/paper.toml";
  auto r = dtwin_test::runTwin(
      "simulate --study " + study +
          " --assembly M3 --scenario lab --set suspension.damping@xx=0.5 --out " +
          (dir / "run.csv").string(),
      dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("unknown place 'xx'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}
