// What changed over several drives (diagnosis/changes_series.hpp) against closed forms: over many
// synthetic series of six dated calibrations whose estimates scatter as their 95 % intervals say,
// the trend's 95 % interval holds the true yearly ratio about 95 % of the time, a car where nothing
// changed gets any value's trend named in at most about 5 % of the series (family-wise), and a
// damper that wears along a straight line on the log scale is named first; the drives are ordered
// by their dates, whatever order they come in.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/statistics.hpp"
#include "diagnosis/changes_series.hpp"

using namespace dtwin;

namespace {

const std::vector<std::string> kDates = {"2026-01-12", "2026-03-09", "2026-05-11",
                                         "2026-07-13", "2026-09-14", "2026-11-16"};

/// A dated calibration (summary.json only): each value `truth(day)` scattered by its log-scale sd.
diag::DatedCalibration drive(const std::string& date, double damping, std::mt19937_64& rng) {
  diag::DatedCalibration d;
  d.date = date;
  EXPECT_TRUE(diag::parseDriveDate(date, d.day)) << date;
  d.folder.dir = "drive_" + date;
  d.folder.assembly = "M1";
  std::normal_distribution<double> n01(0, 1);
  const double z = normalQuantile(0.975);
  const struct {
    const char* name;
    double value, sd;
  } values[] = {{"suspension.stiffness", 30000, 0.01},
                {"suspension.damping", 2500, 0.02},
                {"suspension.damping@fl", damping, 0.03}};
  for (const auto& v : values) {
    const double c = std::log(v.value) + v.sd * n01(rng);
    d.folder.summary["parameters"][v.name] = {
        {"optimum", std::exp(c)}, {"ci95", {std::exp(c - z * v.sd), std::exp(c + z * v.sd)}}};
    d.folder.summary["parameter_order"].push_back(v.name);
    d.folder.summary["units"].push_back(std::string(v.name) == "suspension.stiffness" ? "N/m"
                                                                                      : "1");
    d.folder.summary["bounds"].push_back({0.1, 1e9});
  }
  return d;
}

/// The damper's factor on `date` when it loses `rate` of its damping a year (geometric).
double worn(const std::string& date, double per_year) {
  double day = 0, day0 = 0;
  diag::parseDriveDate(date, day);
  diag::parseDriveDate(kDates.front(), day0);
  return std::pow(per_year, (day - day0) / 365.25);
}

}  // namespace

TEST(ChangesSeries, DatesParseWithAndWithoutATime) {
  double a = 0, b = 0, c = 0;
  ASSERT_TRUE(diag::parseDriveDate("1970-01-02", a));
  EXPECT_DOUBLE_EQ(a, 1.0);
  ASSERT_TRUE(diag::parseDriveDate("2026-03-09T12:00:00Z", b));
  ASSERT_TRUE(diag::parseDriveDate("2026-03-09", c));
  EXPECT_DOUBLE_EQ(b - c, 0.5);
  EXPECT_FALSE(diag::parseDriveDate("2026-13-09", a));
  EXPECT_FALSE(diag::parseDriveDate("09.03.2026", a));
  EXPECT_FALSE(diag::parseDriveDate("12:00:00", a));  // a time without a date
}

TEST(ChangesSeries, TrendIntervalsHoldTheTruthAndAnUnchangedCarIsRarelyNamed) {
  std::mt19937_64 rng(20261208);
  const int series = 2000;
  const double per_year = 0.45;  // the damper keeps 45 % of its damping after a year
  int held = 0, judged = 0, named_unchanged = 0, damper_first = 0;
  for (int k = 0; k < series; ++k) {
    std::vector<diag::DatedCalibration> same, wearing;
    for (const auto& d : kDates) {
      same.push_back(drive(d, 1.0, rng));
      wearing.push_back(drive(d, worn(d, per_year), rng));
    }
    const auto r0 = diag::compareSeries(same, 0.05, "test");
    if (r0.significantCount() > 0) ++named_unchanged;
    for (const auto& v : r0.values) {  // the true yearly ratio is 1 for every value
      ++judged;
      if (v.lo <= 1.0 && 1.0 <= v.hi) ++held;
    }
    const auto r1 = diag::compareSeries(wearing, 0.05, "test");
    ASSERT_EQ(r1.values.size(), 3u);
    for (const auto& v : r1.values)
      if (v.name == "suspension.damping@fl") {
        ++judged;
        if (v.lo <= per_year && per_year <= v.hi) ++held;
      }
    if (r1.values.front().name == "suspension.damping@fl" && r1.values.front().significant)
      ++damper_first;
  }
  const double coverage = static_cast<double>(held) / judged,
               alarms = static_cast<double>(named_unchanged) / series;
  std::printf(
      "trend coverage %.4f over %d values; unchanged car named in %.4f of %d series; the "
      "worn damper named first in %d\n",
      coverage, judged, alarms, series, damper_first);
  EXPECT_NEAR(coverage, 0.95, 0.01);  // binomial sd at n = 8000: 0.0024
  EXPECT_LT(alarms, 0.05 + 3 * std::sqrt(0.05 * 0.95 / series));
  EXPECT_EQ(damper_first, series);
}

TEST(ChangesSeries, DrivesAreOrderedByDateAndTwoOnOneDateAreRefused) {
  std::mt19937_64 rng(7);
  std::vector<diag::DatedCalibration> drives;
  for (const auto& d : {kDates[3], kDates[0], kDates[5], kDates[1]})
    drives.push_back(drive(d, worn(d, 0.5), rng));
  const auto r = diag::compareSeries(drives, 0.05, "test");
  EXPECT_EQ(r.dates, (std::vector<std::string>{kDates[0], kDates[1], kDates[3], kDates[5]}));
  EXPECT_EQ(r.first_to_last.first_dir, "drive_" + kDates[0]);
  EXPECT_EQ(r.first_to_last.second_dir, "drive_" + kDates[5]);
  const std::string text = r.text();
  EXPECT_NE(text.find("suspension.damping@fl fell by"), std::string::npos) << text;
  EXPECT_NE(text.find("first drive to last:"), std::string::npos) << text;
  drives.push_back(drive(kDates[1], 1.0, rng));
  try {
    diag::compareSeries(drives, 0.05, "changes.calibrations");
    ADD_FAILURE() << "two drives on one date were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the same date"), std::string::npos) << e.what();
  }
  drives.resize(2);
  EXPECT_THROW(diag::compareSeries(drives, 0.05, "changes.calibrations"), InputError);
}
