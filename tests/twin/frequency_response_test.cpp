// An independent check of the whole multibody vehicle: at constant speed over a small sinusoidal
// road, with the tires in contact and every law in its linear range, the steady-state vertical
// acceleration at a chassis sensor must equal the frequency response of the linearised vehicle.
// That response is computed here with Eigen from mass, damping and stiffness matrices derived by
// hand from the kinematics (docs/measurements.md, "An independent check"), not from Simbody.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include <Eigen/Dense>

#include "calibration/calibrate.hpp"
#include "io/log_import.hpp"
#include "io/study.hpp"
#include "test_util.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;
using cd = std::complex<double>;

namespace {

constexpr double kTwoPi = 6.283185307179586;

/// The linearised 7-DOF vehicle of M3 (Fiala + MacPherson): q = (heave z, roll φ, pitch θ,
/// u_fl, u_fr, u_rl, u_rr), u the wheel's travel along the chassis z from static.
struct LinearVehicle {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(7, 7), C = Eigen::MatrixXd::Zero(7, 7),
                  K = Eigen::MatrixXd::Zero(7, 7);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 7);  ///< row i: ∂Z_i/∂q, the wheel centre's height
  double kt = 0;

  /// `geometric`: include the geometric stiffness (switched off only to show that it matters).
  explicit LinearVehicle(const Model& m, bool geometric = true) {
    const VehicleData& d = m.vehicle();
    const auto& t = m.table();
    kt = t.value("tire.stiffness");
    const double bt = t.value("tire.damping"), ks = t.value("suspension.stiffness"),
                 cs = t.value("suspension.damping");
    const double w =
        -(d.cg_height - t.value("tire.unloaded_radius_m"));  // wheel centre below the CG, chassis z
    const double mw = d.wheel_mass, iw = 1e-3;  // the wheel bodies' own inertia (simulator)
    M(0, 0) = d.chassis_mass;
    M(1, 1) = d.ixx;
    M(2, 2) = d.iyy;
    for (int c = 0; c < 4; ++c) {
      const double x = isFront(c) ? d.a : -d.b, y = (c % 2 == 0 ? 0.5 : -0.5) * d.track;
      // The wheel's velocity at level attitude: (θ̇ w, −φ̇ w, ż + y φ̇ − x θ̇ + u̇).
      Eigen::VectorXd v = Eigen::VectorXd::Zero(7);
      v(0) = 1;
      v(1) = y;
      v(2) = -x;
      v(3 + c) = 1;
      J.row(c) = v.transpose();
      M += mw * v * v.transpose();
      M(1, 1) += mw * w * w + iw;
      M(2, 2) += mw * w * w + iw;
      // Strut along the slider; tire vertical on the hub (its damper on the hub's velocity).
      K(3 + c, 3 + c) += ks;
      C(3 + c, 3 + c) += cs;
      K += kt * v * v.transpose();
      C += bt * v * v.transpose();
      // Geometric stiffness: the static vertical force on the wheel (= the strut's preload) times
      // the curvature of its height in roll and pitch, ∂²Z/∂φ² = ∂²Z/∂θ² = −w.
      const double G = geometric ? m.staticStrutForce(c) : 0.0;
      K(1, 1) += G * w;
      K(2, 2) += G * w;
    }
  }

  /// Complex amplitude of the vertical acceleration of chassis point (px, py) for road inputs
  /// h_i = Im(H_i e^{jωt}) under the four wheels.
  cd pointAcceleration(double omega, const std::array<cd, 4>& H, double px, double py) const {
    const Eigen::MatrixXcd A =
        -omega * omega * M.cast<cd>() + cd(0, omega) * C.cast<cd>() + K.cast<cd>();
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(7);
    for (int c = 0; c < 4; ++c)
      f += kt * H[static_cast<std::size_t>(c)] * J.row(c).transpose().cast<cd>();
    const Eigen::VectorXcd q = A.partialPivLu().solve(f);
    return -omega * omega * (q(0) + py * q(1) - px * q(2));
  }
};

/// Least-squares a sin ωt + b cos ωt + c over the samples with t >= t_from; returns a + j b.
cd fitSinusoid(const std::vector<double>& t, const std::vector<double>& y, double omega,
               double t_from) {
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < t_from) continue;
    const Eigen::Vector3d phi(std::sin(omega * t[k]), std::cos(omega * t[k]), 1.0);
    N += phi * phi.transpose();
    r += phi * y[k];
  }
  const Eigen::Vector3d c = N.ldlt().solve(r);
  return {c(0), c(1)};
}

}  // namespace

// Three wavelengths at 10 m/s: 12 m (0.83 Hz, body modes), 2.5 m (4 Hz) and 0.9 m (11.1 Hz,
// wheel hop). Left and right tracks differ in phase, so heave, pitch and roll are all excited.
TEST(FrequencyResponse, SensorAccelerationMatchesTheLinearisedVehicle) {
  const auto dir = dtwin_test::freshDir("freq_response");
  const Study s =
      loadStudy(dtwin_test::writeDemoStudy(dir / "study.toml",
                                           "lab_repetitions = 2\n[sensors.p]\nposition_m = [1.1, "
                                           "0.45, 0.2]\nquantity = \"acceleration_z\"\n")
                    .string());
  const auto model = s.makeModel(s.assembly("M3"));
  ASSERT_EQ(model->topology(), SuspensionTopology::MacPherson);
  const LinearVehicle lin(*model), no_geometric(*model, false);
  SimulationOptions o = s.simulation;
  o.accuracy = 1e-7;
  Simulator sim(model, o);
  const double speed = 10.0, amp = 1e-3, wb = model->vehicle().wheelbase(), right_lag = 1.0;  // rad
  double teeth = 0.0;  // how much further the answer without the geometric stiffness lies
  for (double lambda : {12.0, 2.5, 0.9}) {
    SCOPED_TRACE("wavelength " + std::to_string(lambda) + " m");
    const double dx = 0.005, x0 = -wb - 2.0;
    std::vector<double> left, right;
    for (double x = x0; x < 140.0; x += dx) {
      left.push_back(amp * std::sin(kTwoPi * x / lambda));
      right.push_back(amp * std::sin(kTwoPi * x / lambda - right_lag));
    }
    const GridRoad road(x0, dx, left, right, {{"type", "sinusoid"}});
    ScenarioSpec sc;
    sc.name = "sine";
    sc.duration_s = 12.0;
    sc.speed.v_final_mps = speed;
    sc.speed.ramp_s = 0.0;
    const auto run = sim.run(model->defaultRunValues(), road, sc);
    ASSERT_TRUE(run.stats.ok) << run.stats.message;
    // The linear range: every tire stays loaded.
    for (const char* c : {"fl", "fr", "rl", "rr"})
      for (double f : run.trace.column(std::string("hub_force_") + c + "_N")) ASSERT_GT(f, 500.0);
    const double omega = kTwoPi * speed / lambda;
    // Front wheels meet h(v t); rear wheels h(v t − wb); the right track lags by right_lag.
    const double rear = kTwoPi * wb / lambda;
    const std::array<cd, 4> H = {amp * std::exp(cd(0, 0.0)), amp * std::exp(cd(0, -right_lag)),
                                 amp * std::exp(cd(0, -rear)),
                                 amp * std::exp(cd(0, -rear - right_lag))};
    const cd want = lin.pointAcceleration(omega, H, 1.1, 0.45);
    const cd got = fitSinusoid(run.trace.column("time_s"), run.trace.column("p_mps2"), omega, 6.0);
    const double amp_err = std::abs(got) / std::abs(want) - 1.0;
    const double phase_err = std::arg(got / want) * 180.0 / 3.141592653589793;
    std::printf(
        "lambda %5.2f m  f %6.3f Hz  |a| model %.5f  linear %.5f m/s^2  amplitude %+.3f %%  phase "
        "%+.3f deg\n",
        lambda, omega / kTwoPi, std::abs(got), std::abs(want), 100 * amp_err, phase_err);
    EXPECT_LT(std::abs(amp_err), 0.02);
    EXPECT_LT(std::abs(phase_err), 2.0);
    const cd rough = no_geometric.pointAcceleration(omega, H, 1.1, 0.45);
    teeth = std::max(teeth, std::abs(rough - want) / std::abs(got - want));
  }
  // The check has teeth: without the (small) geometric stiffness of the wheels hanging below the
  // centre of mass, the linear answer moves, at the body modes, by far more than the agreement.
  std::printf("without the geometric stiffness the linear answer moves %.0f times further\n",
              teeth);
  EXPECT_GT(teeth, 10.0);
}

// The whole measured path against the same independent answer: a logger's CSV is written from the
// linearised vehicle's steady state (100 Hz with ±1.5 ms of clock jitter, speed in km/h, the road
// under the front wheels in mm, the accelerometer in g with its 1 g offset); `twin import` reads
// it; the twin, driven by the imported speed trace and road log and read at the jittered times on
// the sensor channel, must reproduce it after the transient: within 2 % of the amplitude. (This
// check found that `twin import` once re-wrote the study with its subsystems in alphabetical
// order, which renumbered the assemblies.)
TEST(FrequencyResponse, TheImportedLogOfTheLinearVehicleIsReproduced) {
  const auto dir = dtwin_test::freshDir("freq_response_path");
  const std::string base =
      dtwin_test::writeDemoStudy(dir / "study.toml", "lab_repetitions = 2\n").string();
  const Study s0 = loadStudy(base);
  const auto model0 = s0.makeModel(s0.assembly("M3"));
  const double speed = 10.0, amp = 1e-3, lambda = 2.5, lag = 1.0, g = 9.80665;
  const double omega = kTwoPi * speed / lambda,
               rear = kTwoPi * model0->vehicle().wheelbase() / lambda;
  const std::array<cd, 4> H = {amp * std::exp(cd(0, 0.0)), amp * std::exp(cd(0, -lag)),
                               amp * std::exp(cd(0, -rear)), amp * std::exp(cd(0, -rear - lag))};
  const std::array<double, 3> p{1.1, 0.45, 0.2};
  const cd A = LinearVehicle(*model0).pointAcceleration(omega, H, p[0], p[1]);
  std::string log = "Time,Speed,RoadL,RoadR,Acc\n";
  std::uint64_t state = 99;
  char line[160];
  for (int k = 0; k <= 1200; ++k) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double jitter =
        k == 0 || k == 1200 ? 0.0
                            : (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5) * 0.003;
    const double t = 0.01 * k + jitter;
    const double acc = std::imag(A * std::exp(cd(0, omega * t)));
    std::snprintf(line, sizeof line, "%.5f,36.0,%.6f,%.6f,%.9f\n", 500.0 + t,
                  1e3 * amp * std::sin(omega * t), 1e3 * amp * std::sin(omega * t - lag),
                  1.0 + acc / g);
    log += line;
  }
  ImportMapping m;
  m.source = "test";
  m.time = {"Time", "s", 0, 1, "time", ""};
  m.speed = ImportColumn{"Speed", "km/h", 0, 1, "speed", ""};
  m.road_left = ImportColumn{"RoadL", "mm", 0, 1, "road_left", ""};
  m.road_right = ImportColumn{"RoadR", "mm", 0, 1, "road_right", ""};
  m.channels.push_back({{"Acc", "g", 1.0, 1, "acc", ""}, "p_mps2"});
  SensorSpec sensor;
  sensor.name = "p";
  sensor.position_m = p;
  sensor.noise_sd = 0.01;
  m.sensors.push_back(sensor);
  const ImportResult r = importLog(log, "sine.csv", m, base, "sine");
  writeImport(r, (dir / "imported").string());
  Study s = loadStudy((dir / "imported" / "study.toml").string());
  s.simulation.accuracy = 1e-7;
  const LabData data =
      readLabCsv((dir / "imported" / "measurements.csv").string(), measurableChannels(s.sensors));
  calib::LabObjective obj(s, s.assembly("M3"), {{"sine.csv", "sine", data}}, {});
  const auto eta = obj.predict(dtwin_test::truthOf(s));
  ASSERT_EQ(eta.size(), data.records.size());
  double worst = 0.0;
  int compared = 0;
  for (std::size_t i = 0; i < eta.size(); ++i)
    if (data.records[i].time_s >= 6.0) {
      worst = std::max(worst, std::abs(eta[i] - data.records[i].value));
      ++compared;
    }
  std::printf(
      "imported path: %d samples after 6 s, worst |twin - linear| = %.2e m/s^2 of amplitude %.4f "
      "(%.2f %%)\n",
      compared, worst, std::abs(A), 100 * worst / std::abs(A));
  EXPECT_GT(compared, 550);
  EXPECT_LT(worst, 0.02 * std::abs(A));
}
