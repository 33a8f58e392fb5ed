// The diagnosis tests' lab data (tests/diagnosis/diagnose_e2e_test.cpp, diagnose_corner_test.cpp):
// M1 on the two diagnosis scenarios, diag_bump and diag_rough, 4 hub forces at 200 Hz, 3
// repetitions, with a hidden effect or values set by the caller.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "diagnosis/diagnose.hpp"
#include "study/generate.hpp"

namespace dtwin_test {

/// Lab data of the study's first assembly with `hidden` ("effect:param=value,...", or "" for none)
/// switched on; `more` adjusts the options (hidden values, another effect) before each scenario.
inline std::vector<dtwin::calib::DataSet> diagnosisLabData(
    const dtwin::Study& s, const std::string& hidden, std::uint64_t seed,
    const std::function<void(dtwin::LabOptions&)>& more = {}) {
  std::vector<dtwin::calib::DataSet> sets;
  for (const std::string sc : {"diag_bump", "diag_rough"}) {
    dtwin::LabOptions o;
    o.scenario = sc;
    o.times_mode = dtwin::LabTimesMode::All;
    o.rate_hz = 200.0;
    o.repetitions = 3;
    o.seed = seed;
    o.channels = {"hub_force_fl_N", "hub_force_fr_N", "hub_force_rl_N", "hub_force_rr_N"};
    if (!hidden.empty())
      o.hidden_effects.push_back(dtwin::parseEffectSetting(hidden, "test", s.effectCatalog()));
    if (more) more(o);
    const auto lab = dtwin::generateLab(s, s.assemblies().front(), o);
    sets.push_back({sc + ".csv", sc, lab.data, seed});  // the rough road was made with `seed`
  }
  return sets;
}

/// The diagnosis tests' small sizes: the paper's region with one Latin hypercube of 40 points,
/// 3000 Gibbs iterations (1000 burn-in), two optimiser starts, four confirmations, ten draws in
/// each comparison; the study's other calibration settings (its profile's among them).
inline dtwin::diag::DiagnoseOptions smallDiagnosisOptions(const dtwin::Study& s) {
  dtwin::diag::DiagnoseOptions o;
  o.calibration = dtwin::calib::CalibrationOptions::fromStudy(s);
  o.calibration.lhs_points = 40;
  o.calibration.gibbs_iterations = 3000;
  o.calibration.gibbs_burn_in = 1000;
  o.calibration.optimizer_starts = 2;
  o.calibration.region = "paper";
  o.calibration.design.adaptive = false;
  o.candidates = 4;
  o.compare_draws = 10;
  return o;
}

}  // namespace dtwin_test
