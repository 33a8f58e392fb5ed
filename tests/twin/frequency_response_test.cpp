// An independent check of the whole multibody vehicle: at constant speed over a small sinusoidal
// road, with the tires in contact and every law in its linear range, the steady-state vertical
// acceleration at a chassis sensor must equal the frequency response of the linearised vehicle.
// That response is computed here with Eigen from mass, damping and stiffness matrices derived by
// hand from the kinematics (docs/measurements.md, "An independent check"), not from Simbody.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include <Eigen/Dense>

#include "test_util.hpp"
#include "twin/simulator.hpp"
#include "twin/study.hpp"

using namespace dtwin;
using cd = std::complex<double>;

namespace {

constexpr double kTwoPi = 6.283185307179586;

/// The linearised 7-DOF vehicle of M3 (Fiala + MacPherson): q = (heave z, roll φ, pitch θ,
/// u_fl, u_fr, u_rl, u_rr), u the wheel's travel along the chassis z from static.
struct LinearVehicle {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(7, 7), C = Eigen::MatrixXd::Zero(7, 7), K = Eigen::MatrixXd::Zero(7, 7);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(4, 7);  ///< row i: ∂Z_i/∂q, the wheel centre's height
  double kt = 0;

  /// `geometric`: include the geometric stiffness (switched off only to show that it matters).
  explicit LinearVehicle(const Model& m, bool geometric = true) {
    const VehicleData& d = m.vehicle();
    const auto& t = m.table();
    kt = t.value("tire.stiffness");
    const double bt = t.value("tire.damping"), ks = t.value("suspension.stiffness"), cs = t.value("suspension.damping");
    const double w = -(d.cg_height - t.value("tire.unloaded_radius_m"));  // wheel centre below the CG, chassis z
    const double mw = d.wheel_mass, iw = 1e-3;                            // the wheel bodies' own inertia (simulator)
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
    const Eigen::MatrixXcd A = -omega * omega * M.cast<cd>() + cd(0, omega) * C.cast<cd>() + K.cast<cd>();
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(7);
    for (int c = 0; c < 4; ++c) f += kt * H[static_cast<std::size_t>(c)] * J.row(c).transpose().cast<cd>();
    const Eigen::VectorXcd q = A.partialPivLu().solve(f);
    return -omega * omega * (q(0) + py * q(1) - px * q(2));
  }
};

/// Least-squares a sin ωt + b cos ωt + c over the samples with t >= t_from; returns a + j b.
cd fitSinusoid(const std::vector<double>& t, const std::vector<double>& y, double omega, double t_from) {
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
  const Study s = loadStudy(
      dtwin_test::writeDemoStudy(dir / "study.toml", "lab_repetitions = 2\n[sensors.p]\nposition_m = [1.1, 0.45, 0.2]\nquantity = \"acceleration_z\"\n")
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
    const std::array<cd, 4> H = {amp * std::exp(cd(0, 0.0)), amp * std::exp(cd(0, -right_lag)), amp * std::exp(cd(0, -rear)),
                                 amp * std::exp(cd(0, -rear - right_lag))};
    const cd want = lin.pointAcceleration(omega, H, 1.1, 0.45);
    const cd got = fitSinusoid(run.trace.column("time_s"), run.trace.column("p_mps2"), omega, 6.0);
    const double amp_err = std::abs(got) / std::abs(want) - 1.0;
    const double phase_err = std::arg(got / want) * 180.0 / 3.141592653589793;
    std::printf("lambda %5.2f m  f %6.3f Hz  |a| model %.5f  linear %.5f m/s^2  amplitude %+.3f %%  phase %+.3f deg\n", lambda,
                omega / kTwoPi, std::abs(got), std::abs(want), 100 * amp_err, phase_err);
    EXPECT_LT(std::abs(amp_err), 0.02);
    EXPECT_LT(std::abs(phase_err), 2.0);
    const cd rough = no_geometric.pointAcceleration(omega, H, 1.1, 0.45);
    teeth = std::max(teeth, std::abs(rough - want) / std::abs(got - want));
  }
  // The check has teeth: without the (small) geometric stiffness of the wheels hanging below the
  // centre of mass, the linear answer moves, at the body modes, by far more than the agreement.
  std::printf("without the geometric stiffness the linear answer moves %.0f times further\n", teeth);
  EXPECT_GT(teeth, 10.0);
}
