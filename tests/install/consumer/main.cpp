// One call of each installed library (tests/install/install_test.py): prints "ok" and exits 0 when
// every result is the closed-form or known one, else names the first that is not and exits 1.
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include "calibration/lhs.hpp"
#include "classification/mvn.hpp"
#include "common/distributed.hpp"
#include "common/format.hpp"
#include "diagnosis/signal.hpp"
#include "io/mdf_log.hpp"
#include "io/study.hpp"
#include "report/ticks.hpp"
#include "study/simulate.hpp"
#include "subsystems/tire_law.hpp"
#include "twin/model.hpp"

namespace {
int failures = 0;
void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "consumer: %s\n", what);
    ++failures;
  }
}
}  // namespace

int main() {
  using namespace dtwin;
  // common, distributed
  check(formatFixed(2.5, 2) == "2.50", "common: formatFixed(2.5, 2) is not 2.50");
  check(encodeException(std::make_exception_ptr(std::runtime_error("lost wheel")))
                .find("lost wheel") != std::string::npos,
        "distributed: encodeException lost the message");
  // subsystems, twin
  check(!tireLawNames().empty(), "subsystems: no tire law");
  check(!freeableVehicleParameters().empty(), "twin: no vehicle parameter");
  // calibration: a Latin hypercube of 4 points puts one in each quarter of [0, 1]
  const Eigen::MatrixXd lhs = calib::latinHypercube(4, {0.0}, {1.0}, 7);
  std::vector<int> quarter(4, 0);
  for (int i = 0; i < 4; ++i) ++quarter[std::min(3, static_cast<int>(lhs(i, 0) * 4))];
  check(quarter == std::vector<int>(4, 1), "calibration: the Latin hypercube misses a quarter");
  // classification: ln N(0; 0, 1) = -ln(2 pi) / 2
  const classify::GaussianModel normal(Eigen::VectorXd::Zero(1), Eigen::MatrixXd::Identity(1, 1));
  check(std::abs(normal.logPdf(Eigen::VectorXd::Zero(1)) + 0.5 * std::log(2 * std::acos(-1.0))) <
            1e-14,
        "classification: ln N(0; 0, 1)");
  // diagnosis: times 0, 0.1, ..., 1 make a uniform grid of step 0.1
  std::vector<double> t;
  for (int i = 0; i <= 10; ++i) t.push_back(0.1 * i);
  const diag::UniformGrid grid = diag::uniformGrid(t);
  check(std::abs(grid.dt - 0.1) < 1e-12 && grid.size() == 11,
        "diagnosis: the uniform grid of 11 times");
  // report: the tick step of [0, 153970] for 6 ticks
  check(report::niceStep(0.0, 153970.0) == 50000.0, "report: niceStep");
  // io and mdflib: an MF4 log written and its directory read back
  const std::string mf4 = (std::filesystem::temp_directory_path() /
                           ("dtwin-consumer-" + std::to_string(::getpid()) + ".mf4"))
                              .string();
  MdfWriteGroup group;
  group.name = "drive";
  group.time = {0.0, 0.01, 0.02};
  group.channels.push_back({"seat_acc", "m/s^2", {0.1, 0.2, 0.3}, {}});
  writeMdfLog(mf4, {group}, true);
  std::string bytes;
  {
    std::FILE* f = std::fopen(mf4.c_str(), "rb");
    char buf[4096];
    for (std::size_t n; f && (n = std::fread(buf, 1, sizeof buf, f)) > 0;) bytes.append(buf, n);
    if (f) std::fclose(f);
  }
  std::filesystem::remove(mf4);
  const MdfDirectory dir = readMdfDirectory(bytes, "consumer.mf4");
  check(dir.groups.size() == 1 && dir.groups[0].samples == 3, "io/mdflib: the MF4 log read back");
  // io, study (and twin, Simbody): the demo study's lab scenario, its first 0.2 s, for M1
  Study study = loadStudy(std::string(DTWIN_DATA_DIR) + "/studies/demo.toml");
  for (auto& s : study.scenarios)
    if (s.name == "lab") s.duration_s = 0.2;
  SimulateRequest request;
  request.assembly = "M1";
  request.scenario = "lab";
  request.keep_values = true;
  const std::vector<SimulateRun> runs = simulateScenario(study, request);
  check(runs.size() == 1 && runs[0].ok, "study: the lab run failed");
  if (runs.size() == 1 && runs[0].ok) {
    const std::vector<double>& time = runs[0].values.column("time_s");
    check(!time.empty() && std::abs(time.back() - 0.2) < 1e-9,
          "study: the lab run does not end at 0.2 s");
    check(runs[0].static_hub_force_fl_N > 0, "study: no static hub force");
  }
  if (failures == 0) std::printf("ok\n");
  return failures == 0 ? 0 : 1;
}
