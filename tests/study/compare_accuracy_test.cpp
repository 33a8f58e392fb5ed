// `twin compare` simulates at the accuracy the calibration chose its steps at (summary.json
// integrator_check.accuracy) when that is tighter than the study's [simulation] accuracy: the
// comparison then scores the model the calibration fitted, not the looser integrator's error. On
// the imported demonstration drive, a calibration folder of one row at the truth: with the record
// of a tight accuracy the predictions lie closer to a reference run at 1e-8 than the study's
// accuracy gives, and compare.json says at which accuracy it simulated; a record looser than the
// study's changes nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "nlohmann/json.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

/// compare.json of `twin compare` with a one-row calibration folder whose summary.json has
/// `integrator` as its integrator_check (none when empty).
nlohmann::json compareWith(const fs::path& dir, const std::string& name, const std::string& study,
                           const std::string& integrator) {
  const fs::path cal = dir / ("cal_" + name);
  fs::create_directories(cal);
  dtwin_test::writeText(cal / "summary.json",
                        integrator.empty()
                            ? std::string(R"({"assembly": "M1"})")
                            : R"({"assembly": "M1", "integrator_check": )" + integrator + "}");
  dtwin_test::writeText(
      cal / "posterior.csv",
      "tire.stiffness,tire.damping,suspension.stiffness,suspension.damping,tau,design_index\n"
      "180000,3000,30000,2500,1,0\n");
  const auto r =
      dtwin_test::runTwin("compare --study " + study + " --calibration " + cal.string() +
                              " --data " + (dir / "drive" / "measurements.csv").string() +
                              " --draws 1 --quiet --out " + (dir / ("out_" + name)).string(),
                          dir);
  EXPECT_EQ(r.code, 0) << r.err;
  return nlohmann::json::parse(dtwin_test::slurp(dir / ("out_" + name) / "compare.json"));
}

/// RMS difference of the first series' predictions of two comparisons.
double rmsApart(const nlohmann::json& a, const nlohmann::json& b) {
  const auto& pa = a.at("series").at(0).at("predicted_mean");
  const auto& pb = b.at("series").at(0).at("predicted_mean");
  EXPECT_EQ(pa.size(), pb.size());
  double s = 0.0;
  for (std::size_t i = 0; i < pa.size(); ++i)
    s += std::pow(pa[i].get<double>() - pb[i].get<double>(), 2);
  return std::sqrt(s / static_cast<double>(pa.size()));
}

bool saysAccuracy(const nlohmann::json& j) {
  for (const auto& n : j.value("notes", nlohmann::json::array()))
    if (n.get<std::string>().find("simulated at integrator accuracy") != std::string::npos)
      return true;
  return false;
}

}  // namespace

TEST(CompareAccuracy, ACalibrationsTighterAccuracyIsTheOneCompared) {
  const fs::path dir = dtwin_test::freshDir("compare_accuracy");
  const std::string drive = std::string(DTWIN_SOURCE_DIR) + "/data/drives/";
  const auto r =
      dtwin_test::runTwin("import --log " + drive + "stop_and_go.csv --map " + drive +
                              "stop_and_go_map.toml --quiet --out " + (dir / "drive").string(),
                          dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string study = (dir / "drive" / "study.toml").string();
  // The study's accuracy, and a reference study at 1e-8.
  const std::string text = dtwin_test::slurp(study);
  const auto at = text.find("\naccuracy = ");
  ASSERT_NE(at, std::string::npos) << "the imported study states its accuracy";
  const auto end = text.find('\n', at + 1);
  const double accuracy = std::stod(text.substr(at + 12, end - at - 12));
  const fs::path fine = dir / "drive" / "fine.toml";
  dtwin_test::writeText(fine, text.substr(0, at) + "\naccuracy = 1e-8" + text.substr(end));

  const auto loose = compareWith(dir, "loose", study, "");
  const auto tight =
      compareWith(dir, "tight", study, R"({"accuracy": )" + std::to_string(accuracy / 30) + "}");
  const auto looser =
      compareWith(dir, "looser", study, R"({"accuracy": )" + std::to_string(accuracy * 3) + "}");
  const auto reference = compareWith(dir, "reference", fine.string(), "");

  const double loose_error = rmsApart(loose, reference), tight_error = rmsApart(tight, reference);
  EXPECT_LT(tight_error, 0.5 * loose_error)
      << "the study's accuracy " << accuracy << ": " << loose_error << ", the calibration's "
      << accuracy / 30 << ": " << tight_error;
  EXPECT_TRUE(saysAccuracy(tight)) << tight.dump().substr(0, 2000);
  EXPECT_FALSE(saysAccuracy(loose));
  EXPECT_FALSE(saysAccuracy(looser));
  EXPECT_EQ(rmsApart(looser, loose), 0.0) << "a looser record than the study's changes nothing";
}
