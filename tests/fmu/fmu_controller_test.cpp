// A controller outside the twin drives it through the FMU: a skyhook written here, in the test,
// reads the body's vertical velocity over each strut (outputs body_vz_*_mps) and sets each
// actuator force input to -c_sky times it, every 1 ms. It must match the catalogue's `skyhook`
// effect run inside the twin (`twin simulate --effect skyhook:damping=c_sky`). fmusim cannot close
// such a loop (it reads inputs from a file), so the FMU is loaded here by a tiny FMI 2.0 importer
// of its own: dlopen of the unzipped library, the fmi2 calls in the order the standard fixes.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdarg>
#include <cstdio>

#include <fmi2Functions.h>
#include "fmu/fmu_test_util.hpp"

namespace {

namespace fs = std::filesystem;
using dtwin_test::runTwin;

void logger(fmi2ComponentEnvironment, fmi2String name, fmi2Status status, fmi2String category,
            fmi2String message, ...) {
  va_list args;
  va_start(args, message);
  std::fprintf(stderr, "[%s %d %s] ", name, static_cast<int>(status), category);
  std::vfprintf(stderr, message, args);
  std::fputc('\n', stderr);
  va_end(args);
}

/// The fmi2 functions of one unzipped FMU.
struct Fmu {
  void* lib = nullptr;
  fmi2InstantiateTYPE* instantiate = nullptr;
  fmi2FreeInstanceTYPE* free_instance = nullptr;
  fmi2SetupExperimentTYPE* setup = nullptr;
  fmi2EnterInitializationModeTYPE* enter_init = nullptr;
  fmi2ExitInitializationModeTYPE* exit_init = nullptr;
  fmi2SetRealTYPE* set_real = nullptr;
  fmi2GetRealTYPE* get_real = nullptr;
  fmi2DoStepTYPE* do_step = nullptr;
  fmi2TerminateTYPE* terminate = nullptr;
  explicit Fmu(const fs::path& so) {
    lib = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib) return;
    auto sym = [&](auto& f, const char* name) {
      f = reinterpret_cast<std::remove_reference_t<decltype(f)>>(dlsym(lib, name));
    };
    sym(instantiate, "fmi2Instantiate");
    sym(free_instance, "fmi2FreeInstance");
    sym(setup, "fmi2SetupExperiment");
    sym(enter_init, "fmi2EnterInitializationMode");
    sym(exit_init, "fmi2ExitInitializationMode");
    sym(set_real, "fmi2SetReal");
    sym(get_real, "fmi2GetReal");
    sym(do_step, "fmi2DoStep");
    sym(terminate, "fmi2Terminate");
  }
  ~Fmu() {
    if (lib) dlclose(lib);
  }
  bool complete() const {
    return instantiate && free_instance && setup && enter_init && exit_init && set_real &&
           get_real && do_step && terminate;
  }
};

}  // namespace

TEST(FmuController, SkyhookOutsideMatchesTheSkyhookEffectInside) {
  constexpr double c_sky = 2500.0, dt = 1e-3;
  const fs::path d = dtwin_test::freshDir("fmu_controller");
  const fs::path calib = fmu_test::writeCalibration(d / "calib" / "M1");
  const auto ex = runTwin("export-fmu --study " + fmu_test::demoStudy() + " --calibration " +
                              calib.string() + " --out " + (d / "m1.fmu").string(),
                          d);
  ASSERT_EQ(ex.code, 0) << ex.err;
  fmu_test::unzipTo(d / "m1.fmu", d / "m1");
  const std::string xml = dtwin_test::slurp(d / "m1" / "modelDescription.xml");
  const auto vr = fmu_test::valueReferences(xml);
  std::smatch guid;
  ASSERT_TRUE(std::regex_search(xml, guid, std::regex("guid=\"([^\"]+)\"")));
  Fmu fmu(d / "m1" / "binaries" / "linux64" / "twin_demo_M1.so");
  ASSERT_TRUE(fmu.lib) << dlerror();
  ASSERT_TRUE(fmu.complete());
  const fmi2CallbackFunctions cb = {logger, calloc, free, nullptr, nullptr};
  const std::string uri = "file://" + (d / "m1" / "resources").string() + "/";
  fmi2Component c = fmu.instantiate("skyhook", fmi2CoSimulation, guid[1].str().c_str(), uri.c_str(),
                                    &cb, fmi2False, fmi2False);
  ASSERT_TRUE(c);
  const char* corners[] = {"fl", "fr", "rl", "rr"};
  std::vector<fmi2ValueReference> in_vr = {vr.at("in_speed_mps")}, act_vr, vz_vr;
  for (const char* k : corners) in_vr.push_back(vr.at(std::string("in_road_") + k + "_m"));
  for (const char* k : corners) act_vr.push_back(vr.at(std::string("in_actuator_") + k + "_N"));
  for (const char* k : corners) vz_vr.push_back(vr.at(std::string("body_vz_") + k + "_mps"));
  const std::vector<std::string> compared = {
      "chassis_heave_m", "chassis_pitch_rad", "chassis_pitch_acc_radps2", "chassis_heave_acc_mps2",
      "hub_force_fl_N",  "hub_force_rr_N",    "susp_defl_fl_m",           "susp_defl_rl_m"};
  std::vector<fmi2ValueReference> out_vr;
  for (const auto& n : compared) out_vr.push_back(vr.at(n));
  const auto in = fmu_test::scenarioInputs("diag_bump", dt);
  auto setInputs = [&](std::size_t k) {
    std::vector<double> v = {in.speed[k]};
    for (double h : in.road[k]) v.push_back(h);
    ASSERT_EQ(fmu.set_real(c, in_vr.data(), in_vr.size(), v.data()), fmi2OK);
  };
  ASSERT_EQ(fmu.setup(c, fmi2False, 0.0, 0.0, fmi2True, 3.0), fmi2OK);
  ASSERT_EQ(fmu.enter_init(c), fmi2OK);
  setInputs(0);
  ASSERT_EQ(fmu.exit_init(c), fmi2OK);
  fmu_test::Table rows;
  rows.names = {"time"};
  for (const auto& n : compared) rows.names.push_back(n);
  rows.cols.resize(rows.names.size());
  auto record = [&](double t) {
    std::vector<double> y(out_vr.size());
    ASSERT_EQ(fmu.get_real(c, out_vr.data(), out_vr.size(), y.data()), fmi2OK);
    rows.cols[0].push_back(t);
    for (std::size_t i = 0; i < y.size(); ++i) rows.cols[i + 1].push_back(y[i]);
  };
  record(0.0);
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k + 1 < in.t.size(); ++k) {
    // The controller: the body's velocity over each strut now, the force held over the step.
    std::array<double, 4> vz{}, force{};
    ASSERT_EQ(fmu.get_real(c, vz_vr.data(), 4, vz.data()), fmi2OK);
    for (std::size_t i = 0; i < 4; ++i) force[i] = -c_sky * vz[i];
    ASSERT_EQ(fmu.set_real(c, act_vr.data(), 4, force.data()), fmi2OK);
    setInputs(k);
    ASSERT_EQ(fmu.do_step(c, in.t[k], in.t[k + 1] - in.t[k], fmi2True), fmi2OK) << in.t[k];
    record(in.t[k + 1]);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(fmu.terminate(c), fmi2OK);
  fmu.free_instance(c);
  std::printf(
      "controller loop: %zu steps of 1 ms in %.2f s wall (%.0f us per step: get, set, "
      "doStep)\n",
      in.t.size() - 1, wall, 1e6 * wall / static_cast<double>(in.t.size() - 1));
  // Inside: the skyhook effect; and without any controller, to show the skyhook matters here.
  const auto sky = runTwin("simulate --study " + fmu_test::demoStudy() +
                               " --assembly M1 --scenario diag_bump" + fmu_test::setCalibrated() +
                               " --effect skyhook:damping=2500 --out " + (d / "sky.csv").string(),
                           d);
  ASSERT_EQ(sky.code, 0) << sky.err;
  const auto off =
      runTwin("simulate --study " + fmu_test::demoStudy() + " --assembly M1 --scenario diag_bump" +
                  fmu_test::setCalibrated() + " --out " + (d / "off.csv").string(),
              d);
  ASSERT_EQ(off.code, 0) << off.err;
  const auto a = fmu_test::readCsv(d / "sky.csv"), b = fmu_test::readCsv(d / "off.csv");
  for (const auto& n : compared) {
    const auto inside = fmu_test::compare(rows, a, n, 1e-3),
               passive = fmu_test::compare(rows, b, n, 1e-3);
    ASSERT_GE(inside.rows, 2999u) << n;
    std::printf("  %-24s max |outside - inside| %.3e (%.2f %% of range); vs no skyhook %.3e\n",
                n.c_str(), inside.max_abs, 100 * inside.max_abs / inside.range, passive.max_abs);
    EXPECT_LE(inside.max_abs, 0.01 * inside.range) << n;
    EXPECT_LE(inside.max_abs, 0.2 * passive.max_abs) << n << ": the skyhook changes it far more";
  }
}
