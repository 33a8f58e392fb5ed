// Synthetic measurements (study/generate.hpp): automatic lab times, noise statistics, [lab]
// settings, determinism whatever the thread count, independent roads per field run with a common
// smooth part, failed runs named with their seed, and parallelFor's error propagation.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>

#include "common/errors.hpp"
#include "common/parallel.hpp"
#include "shipped_study.hpp"
#include "study/generate.hpp"
#include "twin/simulator.hpp"

using namespace dtwin;

namespace {
const std::string kSrc = DTWIN_SOURCE_DIR;

std::string readFile(const std::string& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The demo study with `extra` appended, written where its vehicle path still resolves.
std::string demoWith(const std::string& name, const std::string& extra) {
  std::string text = readFile(kSrc + "/data/studies/demo.toml");
  const std::string veh = "vehicle = \"../vehicle/midsize_sedan.toml\"";
  text.replace(text.find(veh), veh.size(),
               "vehicle = \"" + kSrc + "/data/vehicle/midsize_sedan.toml\"");
  const std::string path = ::testing::TempDir() + "/" + name + ".toml";
  std::ofstream(path) << text << "\n" << extra;
  return path;
}

std::string studyError(const std::string& path) {
  try {
    loadStudy(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

const Study& demo() { return dtwin_test::shippedStudy("demo"); }

Trace syntheticTrace(const std::vector<double>& x, double rate = 1000.0) {
  Trace t;
  t.addChannel({"time_s", "s", ""});
  t.addChannel({"hub_force_fl_N", "N", ""});
  for (std::size_t k = 0; k < x.size(); ++k) {
    t.column(0).push_back(static_cast<double>(k) / rate);
    t.column(1).push_back(x[k]);
  }
  return t;
}

bool isLocalExtremum(const std::vector<double>& x, std::size_t k) {
  if (k == 0 || k + 1 >= x.size()) return false;
  // Walk over a flat run to the neighbouring different values.
  std::size_t lo = k, hi = k;
  while (lo > 0 && x[lo - 1] == x[k]) --lo;
  while (hi + 1 < x.size() && x[hi + 1] == x[k]) ++hi;
  if (lo == 0 || hi + 1 >= x.size()) return false;
  return (x[k] > x[lo - 1] && x[k] > x[hi + 1]) || (x[k] < x[lo - 1] && x[k] < x[hi + 1]);
}

}  // namespace

TEST(AutomaticTimes, RankedSeparatedExtremaInTimeOrder) {
  // Static value 0; extrema at 100 ms (+5), 110 ms (-9, within 20 ms of the +5 and larger),
  // 300 ms (+2), a flat minimum -4 from 500 to 510 ms, and one at 50 ms before the obstacle.
  std::vector<double> x(1001, 0.0);
  auto peak = [&](std::size_t k, double v) {
    x[k] = v;
    x[k - 1] = v / 2;
    x[k + 1] = v / 2;
  };
  peak(50, 100.0);
  peak(100, 5.0);
  peak(110, -9.0);
  peak(300, 2.0);
  for (std::size_t k = 499; k <= 511; ++k) x[k] = -2.0;
  for (std::size_t k = 500; k <= 510; ++k) x[k] = -4.0;
  const Trace t = syntheticTrace(x);
  EXPECT_EQ(automaticLabTimes(t, "hub_force_fl_N", 0.08, 3, 0.02),
            (std::vector<double>{0.11, 0.3, 0.505}));
  EXPECT_EQ(automaticLabTimes(t, "hub_force_fl_N", 0.08, 2, 0.02),
            (std::vector<double>{0.11, 0.505}));
  EXPECT_EQ(automaticLabTimes(t, "hub_force_fl_N", 0.08, 10, 0.0),
            (std::vector<double>{0.1, 0.11, 0.3, 0.505}));
  EXPECT_EQ(automaticLabTimes(t, "hub_force_fl_N", 0.0, 1, 0.02), (std::vector<double>{0.05}));
  EXPECT_TRUE(automaticLabTimes(syntheticTrace(std::vector<double>(100, 1.0)), "hub_force_fl_N",
                                0.0, 5, 0.02)
                  .empty());
}

TEST(GenerateLab, AutomaticTimesAreSeparatedExtremaOfTheNoiseFreeResponse) {
  LabOptions opt;
  opt.repetitions = 2;
  const LabResult r = generateLab(demo(), demo().assemblies().front(), opt);
  ASSERT_EQ(r.times_s.size(), 5u);
  const auto& x = r.noise_free.column("hub_force_fl_N");
  const auto& time = r.noise_free.column("time_s");
  const double static_value = x.front();
  double smallest_kept = 1e300;
  for (std::size_t i = 0; i < r.times_s.size(); ++i) {
    const double t = r.times_s[i];
    const auto k = static_cast<std::size_t>(std::llround(t * 1000.0));
    EXPECT_EQ(time[k], t) << "on the 1 kHz grid";
    EXPECT_GE(t, 6.0) << "at or after the bump";
    EXPECT_TRUE(isLocalExtremum(x, k)) << t;
    if (i) {
      EXPECT_GE(t - r.times_s[i - 1], 0.02 - 1e-12) << "separation";
    }
    smallest_kept = std::min(smallest_kept, std::abs(x[k] - static_value));
  }
  // Any larger extremum that was not kept lies within 20 ms of a kept time.
  for (std::size_t k = 6000; k + 1 < x.size(); ++k) {
    if (!isLocalExtremum(x, k)) continue;
    std::size_t hi = k;  // a flat extremum counts once, at its middle sample
    while (hi + 1 < x.size() && x[hi + 1] == x[k]) ++hi;
    const std::size_t mid = (k + hi) / 2;
    k = hi;
    if (std::abs(x[mid] - static_value) <= smallest_kept) continue;
    bool near = false;
    for (double t : r.times_s) near = near || std::abs(time[mid] - t) < 0.02;
    EXPECT_TRUE(near) << "extremum at " << time[mid] << " larger than a kept one";
  }
  EXPECT_EQ(r.provenance["lab"]["times"]["source"], "automatic");
  EXPECT_EQ(r.data.records.size(), 2u * 5u);
}

TEST(GenerateLab, NoiseHasTheStudyVariance) {
  LabOptions opt;
  opt.repetitions = 400;
  const Study& s = demo();
  const LabResult r = generateLab(s, s.assemblies().front(), opt);
  ASSERT_EQ(r.data.records.size(), 400u * r.times_s.size());
  const auto& clean = r.noise_free.column("hub_force_fl_N");
  double sum = 0, sum2 = 0;
  for (const auto& rec : r.data.records) {
    EXPECT_EQ(rec.channel, "hub_force_fl_N");
    const double e = rec.value - clean[static_cast<std::size_t>(std::llround(rec.time_s * 1000.0))];
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(r.data.records.size());
  const double mean = sum / n, var = (sum2 - n * mean * mean) / (n - 1);
  const double s2 = s.noise_variance_N2;
  EXPECT_LT(std::abs(mean), 4 * std::sqrt(s2 / n));
  EXPECT_LT(std::abs(var - s2), 4 * s2 * std::sqrt(2.0 / (n - 1))) << "sample variance " << var;
  EXPECT_DOUBLE_EQ(r.provenance["noise"]["variance_N2"].get<double>(), 18000.0);
  EXPECT_EQ(r.provenance["truth"]["tire.stiffness"]["value"].get<double>(), 180e3);

  // Repetition r's noise depends on (seed, r) only: the first repetitions are the same when more
  // are asked for; another seed gives other values.
  LabOptions few = opt;
  few.repetitions = 3;
  const LabResult r3 = generateLab(s, s.assemblies().front(), few);
  for (std::size_t i = 0; i < r3.data.records.size(); ++i)
    EXPECT_EQ(r3.data.records[i].value, r.data.records[i].value);
  few.seed = 7;
  const LabResult r7 = generateLab(s, s.assemblies().front(), few);
  EXPECT_NE(r7.data.records[0].value, r3.data.records[0].value);
  EXPECT_EQ(r7.provenance["seed"], 7);
}

TEST(GenerateLab, StudyChoosesTimesAndChannels) {
  const Study s = loadStudy(demoWith(
      "lab_explicit",
      "[lab]\ntimes_s = [6.1, 6.25, 7.0]\nchannels = [\"hub_force_fl_N\", \"susp_defl_fl_m\"]\n"));
  LabOptions opt;
  opt.repetitions = 2;
  const LabResult r = generateLab(s, s.assembly("M3"), opt);
  EXPECT_EQ(r.times_s, (std::vector<double>{6.1, 6.25, 7.0}));
  ASSERT_EQ(r.data.records.size(), 2u * 2u * 3u);
  EXPECT_EQ(r.data.channels(), (std::vector<std::string>{"hub_force_fl_N", "susp_defl_fl_m"}));
  const auto& defl = r.noise_free.column("susp_defl_fl_m");
  for (const auto& rec : r.data.records) {
    if (rec.channel == "susp_defl_fl_m") {
      EXPECT_EQ(rec.value, defl[static_cast<std::size_t>(std::llround(rec.time_s * 1000))]);
    }
  }
  EXPECT_EQ(r.provenance["noise"]["not_applied_to"], nlohmann::json::array({"susp_defl_fl_m"}));
  EXPECT_EQ(r.provenance["assembly"]["id"], "M3");
  EXPECT_EQ(r.provenance["lab"]["times"]["source"], "explicit");

  const Study a =
      loadStudy(demoWith("lab_auto3", "[lab]\nauto_times = 3\nmin_separation_s = 0.1\n"));
  const LabResult r3 = generateLab(a, a.assemblies().front(), opt);
  ASSERT_EQ(r3.times_s.size(), 3u);
  EXPECT_GE(r3.times_s[1] - r3.times_s[0], 0.1 - 1e-9);
  EXPECT_GE(r3.times_s[2] - r3.times_s[1], 0.1 - 1e-9);
}

TEST(GenerateLab, BadLabTablesAreInputErrors) {
  struct Case {
    std::string extra, expect;
  };
  const std::vector<Case> cases = {
      {"[lab]\ntime_s = [6.1]\n", "lab.time_s: unknown field (did you mean 'times_s'?)"},
      {"[lab]\nchannels = [\"hub_force_lf_N\"]\n",
       "lab.channels: unknown channel 'hub_force_lf_N'"},
      {"[lab]\nchannels = [\"susp_defl_fl_m\", \"susp_defl_fl_m\"]\n",
       "channel 'susp_defl_fl_m' listed twice"},
      {"[lab]\ntimes_s = [6.1, 6.0]\n",
       "lab.times_s: element 1 (6.000000) must be greater than the one before it"},
      {"[lab]\ntimes_s = [6.1005]\n", "is not on the output grid"},
      {"[lab]\ntimes_s = []\n", "must list at least one time"},
      {"[lab]\ntimes_s = [6.1]\nauto_times = 3\n",
       "lab.auto_times: give either times_s or auto_times, not both"},
      {"[lab]\nauto_times = 0\n", "lab.auto_times: must be a positive integer, got 0"},
      {"[lab]\nauto_times = 2.5\n", "lab.auto_times: must be an integer"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.extra);
    const std::string e = studyError(demoWith("lab_bad", c.extra));
    EXPECT_NE(e.find(c.expect), std::string::npos) << e;
    EXPECT_NE(e.find("lab_bad.toml:"), std::string::npos) << e;
  }
  // A time after the end of the scenario is found when the lab data are made.
  const Study s = loadStudy(demoWith("lab_late", "[lab]\ntimes_s = [16.0]\n"));
  try {
    generateLab(s, s.assemblies().front());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("lab.times_s[0]: 16 s lies outside the scenario (0 .. 15 s)"),
        std::string::npos)
        << e.what();
  }
}

TEST(GenerateField, SameBytesWithOneOrTwoThreadsAndARoadPerRun) {
  FieldOptions opt;
  opt.runs = 4;
  opt.threads = 1;
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  const FieldResult one =
      generateField(demo(), demo().assemblies().front(), opt, [&](std::size_t d, std::size_t n) {
        calls.push_back({d, n});
      });
  opt.threads = 2;
  const FieldResult two = generateField(demo(), demo().assemblies().front(), opt);
  EXPECT_EQ(fieldCsvText(one.data), fieldCsvText(two.data))
      << "byte-identical whatever the thread count";
  EXPECT_EQ(two.provenance["field"]["threads"], 2);
  ASSERT_EQ(calls.size(), 5u);
  EXPECT_EQ(calls.back(), (std::pair<std::size_t, std::size_t>{4, 4}));

  const FieldData& d = one.data;
  ASSERT_EQ(d.rowCount(), 4u);
  ASSERT_EQ(d.columnCount(), 5001u);
  EXPECT_EQ(d.times_s.front(), 10.0);
  EXPECT_EQ(d.times_s.back(), 15.0);
  EXPECT_EQ(d.runs, (std::vector<long>{1, 2, 3, 4}));
  std::set<std::uint64_t> seeds(d.road_seeds.begin(), d.road_seeds.end());
  EXPECT_EQ(seeds.size(), 4u) << "a different road per run";
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(d.road_seeds[i], fieldRoadSeed(demo().seed, i + 1));
    EXPECT_LT(d.road_seeds[i], 1ULL << 53);
  }
  double diff = 0;
  for (std::size_t k = 0; k < d.columnCount(); ++k)
    diff = std::max(diff, std::abs(d.at(0, k) - d.at(1, k)));
  EXPECT_GT(diff, 1000.0) << "class-D roads give different forces";
  EXPECT_EQ(one.provenance["field"]["per_run"][2]["road_seed"], d.road_seeds[2]);
}

TEST(GenerateField, SmoothPartIsCommonAndNoiseHasTheStudyVariance) {
  FieldOptions opt;
  opt.runs = 2;
  opt.t_begin_s = 0.0;
  opt.t_end_s = 15.0;
  opt.noise_variance_N2 = 0.0;
  const FieldResult clean = generateField(demo(), demo().assemblies().front(), opt);
  const FieldData& c = clean.data;
  ASSERT_EQ(c.columnCount(), 15001u);
  // The road is flat until the front axle reaches it at 6 s. The integrator lands on a knot at
  // 6 s - obstacle_margin_before_s (5.98 s) and never evaluates beyond it before, so samples up
  // to 5.98 s are bit-identical.
  for (std::size_t k = 0; k <= 5980; ++k)
    ASSERT_EQ(c.at(0, k), c.at(1, k)) << "t = " << c.times_s[k];
  double diff = 0;
  for (std::size_t k = 6500; k < c.columnCount(); ++k)
    diff = std::max(diff, std::abs(c.at(0, k) - c.at(1, k)));
  EXPECT_GT(diff, 1000.0);

  opt.noise_variance_N2.reset();
  const FieldResult noisy = generateField(demo(), demo().assemblies().front(), opt);
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < c.values.size(); ++i) {
    const double e = noisy.data.values[i] - c.values[i];
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(c.values.size()), s2 = demo().noise_variance_N2;
  const double mean = sum / n, var = (sum2 - n * mean * mean) / (n - 1);
  EXPECT_LT(std::abs(mean), 4 * std::sqrt(s2 / n));
  EXPECT_LT(std::abs(var - s2), 4 * s2 * std::sqrt(2.0 / (n - 1))) << "sample variance " << var;
}

TEST(GenerateField, FailedRunIsReportedWithItsSeed) {
  Study s = demo();
  s.simulation.max_internal_steps = 50;  // every run fails
  FieldOptions opt;
  opt.runs = 3;
  opt.threads = 2;
  try {
    generateField(s, s.assemblies().front(), opt);
    ADD_FAILURE() << "no error";
  } catch (const RunFailedError& e) {
    EXPECT_EQ(e.run(), 1u) << "the lowest failing run, whatever the thread count";
    EXPECT_EQ(e.seed(), fieldRoadSeed(s.seed, 1));
    const std::string w = e.what();
    EXPECT_NE(w.find("field run 1 of 3 (road seed " + std::to_string(e.seed()) + ") failed: "),
              std::string::npos)
        << w;
    EXPECT_NE(
        w.find("twin simulate --assembly M1 --scenario field --seed " + std::to_string(e.seed())),
        std::string::npos)
        << w;
  }
  FieldOptions bad;
  bad.runs = 1;
  bad.channel = "hub_force_fl_kN";
  EXPECT_THROW(generateField(demo(), demo().assemblies().front(), bad), InputError);
  bad.channel = "hub_force_fl_N";
  bad.t_begin_s = 10.0005;
  EXPECT_THROW(generateField(demo(), demo().assemblies().front(), bad), InputError);
}

TEST(ParallelFor, EveryIndexOnceAndLowestErrorRethrown) {
  for (int threads : {1, 2, 4}) {
    std::vector<std::atomic<int>> hits(100);
    parallelFor(hits.size(), threads, [&](std::size_t i, int w) {
      EXPECT_GE(w, 0);
      EXPECT_LT(w, workerCount(threads, hits.size()));
      hits[i]++;
    });
    for (auto& h : hits) EXPECT_EQ(h.load(), 1);
    try {
      parallelFor(50, threads, [](std::size_t i, int) {
        if (i == 7 || i == 30) throw std::runtime_error("task " + std::to_string(i));
      });
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "task 7");
    }
  }
  EXPECT_EQ(workerCount(8, 3), 3);
  EXPECT_EQ(workerCount(0, 0), 1);
  EXPECT_GE(workerCount(0, 1000), 1);
}

// --- hidden effects and dense lab data (diagnosis) ---

namespace {
EffectSetting hidden(const std::string& text) {
  return parseEffectSetting(text, "--hidden-effect", EffectCatalog{});
}

LabOptions denseBump() {
  LabOptions opt;
  opt.scenario = "diag_bump";
  opt.repetitions = 2;
  opt.times_mode = LabTimesMode::All;
  opt.channels = {"hub_force_fl_N", "susp_defl_fl_m"};
  return opt;
}
}  // namespace

TEST(GenerateLabHidden, BumpStopChangesTheBumpAndNothingBefore) {
  const Study& s = demo();
  const LabResult base = generateLab(s, s.assemblies().front(), denseBump());
  LabOptions opt = denseBump();
  opt.hidden_effects = {hidden("bump_stop:stiffness=2e6,gap_m=0.02")};
  const LabResult hid = generateLab(s, s.assemblies().front(), opt);
  ASSERT_EQ(base.data.records.size(), hid.data.records.size());
  ASSERT_EQ(base.data.records.size(), 2u * 2u * 3001u) << "every 1 kHz sample of the 3 s scenario";
  EXPECT_FALSE(base.provenance.contains("hidden_effects"));

  // Before the bump (front wheels meet it at 1 s; the integrator lands on 1 s - 0.02 s) the
  // stop is not touched: bit-identical, noise included (same seed, same streams).
  std::size_t before = 0;
  for (std::size_t i = 0; i < base.data.records.size(); ++i) {
    const auto& a = base.data.records[i];
    const auto& b = hid.data.records[i];
    ASSERT_EQ(a.time_s, b.time_s);
    ASSERT_EQ(a.channel, b.channel);
    if (a.time_s <= 0.98) {
      ASSERT_EQ(a.value, b.value) << a.channel << " at t = " << a.time_s;
      ++before;
    }
  }
  EXPECT_EQ(before, 2u * 2u * 981u);

  // At the bump peak (largest noise-free front-left suspension compression of the base run,
  // beyond the 0.02 m gap) the stop pushes: the hub force differs there (noise-free and noisy).
  const auto& d0 = base.noise_free.column("susp_defl_fl_m");
  const auto& f0 = base.noise_free.column("hub_force_fl_N");
  const auto& f1 = hid.noise_free.column("hub_force_fl_N");
  const auto k_peak = static_cast<std::size_t>(std::max_element(d0.begin(), d0.end()) - d0.begin());
  const double t_peak = base.noise_free.column("time_s")[k_peak];
  EXPECT_GT(t_peak, 1.0);
  EXPECT_LT(t_peak, 2.2);
  EXPECT_GT(d0[k_peak], 0.025) << "the stop (gap 0.02 m) is engaged at the peak";
  EXPECT_GT(std::abs(f1[k_peak] - f0[k_peak]), 10.0)
      << "base " << f0[k_peak] << " N, hidden " << f1[k_peak] << " N";
  EXPECT_NE(hid.noise_free.column("susp_defl_fl_m")[k_peak], d0[k_peak]);
  for (std::size_t i = 0; i < base.data.records.size(); ++i) {
    if (base.data.records[i].time_s == t_peak) {
      EXPECT_NE(base.data.records[i].value, hid.data.records[i].value);
    }
  }
  double max_diff = 0;
  for (std::size_t k = 0; k < f0.size(); ++k)
    max_diff = std::max(max_diff, std::abs(f1[k] - f0[k]));
  EXPECT_GT(max_diff, 30.0);

  // The sidecar records every parameter of the hidden effect with the value used.
  const auto& h = hid.provenance["hidden_effects"];
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0]["name"], "bump_stop");
  EXPECT_EQ(h[0]["parameters"]["stiffness"].get<double>(), 2e6);
  EXPECT_EQ(h[0]["parameters"]["gap_m"].get<double>(), 0.02);
  EXPECT_EQ(h[0]["parameters"]["exponent"].get<double>(), 2.0)
      << "the default of a parameter not given";
  EXPECT_EQ(hiddenEffectsSummary(h, EffectCatalog{}),
            "bump_stop (exponent=2, gap_m=0.02 m, stiffness=2e+06 N/m^n)");
}

TEST(GenerateLabHidden, EffectAtItsOffValuesGivesTheBaseDataBitForBit) {
  const Study& s = demo();
  const LabResult base = generateLab(s, s.assemblies().front(), denseBump());
  LabOptions opt = denseBump();
  opt.hidden_effects = {hidden("bump_stop")};
  const LabResult off = generateLab(s, s.assemblies().front(), opt);
  ASSERT_EQ(base.data.records.size(), off.data.records.size());
  for (std::size_t i = 0; i < base.data.records.size(); ++i)
    ASSERT_EQ(base.data.records[i].value, off.data.records[i].value) << i;
  EXPECT_EQ(labCsvText(base.data), labCsvText(off.data));
  EXPECT_EQ(off.provenance["hidden_effects"][0]["parameters"]["stiffness"].get<double>(), 0.0);
  EXPECT_EQ(off.provenance["hidden_effects"][0]["parameters"]["gap_m"].get<double>(), 0.05);
  EXPECT_EQ(off.provenance["hidden_effects"][0]["given"], nlohmann::json::array());
}

TEST(GenerateLabDense, WindowAndRateGiveEveryDecimatedSample) {
  const Study& s = demo();
  LabOptions opt = denseBump();
  opt.repetitions = 3;
  opt.window = std::make_pair(0.9, 1.2);
  opt.rate_hz = 200.0;
  const LabResult r = generateLab(s, s.assemblies().front(), opt);
  std::vector<double> expected;
  for (int k = 900; k <= 1200; k += 5) expected.push_back(k / 1000.0);
  ASSERT_EQ(expected.size(), 61u);
  EXPECT_EQ(expected[1], 0.905);
  EXPECT_EQ(expected.back(), 1.2);
  EXPECT_EQ(r.times_s, expected);
  std::map<std::pair<long, std::string>, std::vector<double>> times;
  for (const auto& rec : r.data.records) times[{rec.repetition, rec.channel}].push_back(rec.time_s);
  ASSERT_EQ(times.size(), 3u * 2u);
  for (const auto& [key, t] : times)
    EXPECT_EQ(t, expected) << "repetition " << key.first << " " << key.second;
  // Noise on the channel in N only; the values are the noise-free samples at those times.
  const auto& defl = r.noise_free.column("susp_defl_fl_m");
  const auto& force = r.noise_free.column("hub_force_fl_N");
  int noisy = 0;
  for (const auto& rec : r.data.records) {
    const auto k = static_cast<std::size_t>(std::llround(rec.time_s * 1000.0));
    if (rec.channel == "susp_defl_fl_m")
      EXPECT_EQ(rec.value, defl[k]);
    else
      noisy += rec.value != force[k];
  }
  EXPECT_EQ(noisy, 3 * 61);
  const auto& tj = r.provenance["lab"]["times"];
  EXPECT_EQ(tj["source"], "all");
  EXPECT_EQ(r.times_rule, "all samples in [0.9,1.2] at 200 Hz");
  EXPECT_NE(tj["rule"].get<std::string>().find("all samples in [0.9,1.2] at 200 Hz"),
            std::string::npos);
  EXPECT_EQ(tj["step"], 5);
  EXPECT_EQ(tj["count"], 61);
  EXPECT_EQ(r.provenance["lab"]["channels"].size(), 2u);

  // Defaults: the whole scenario at the output rate.
  LabOptions whole = denseBump();
  whole.repetitions = 1;
  whole.channels = {"susp_defl_fl_m"};
  const LabResult w = generateLab(s, s.assemblies().front(), whole);
  ASSERT_EQ(w.times_s.size(), 3001u);
  EXPECT_EQ(w.times_s.front(), 0.0);
  EXPECT_EQ(w.times_s.back(), 3.0);
  EXPECT_EQ(w.times_rule, "all samples in [0,3] at 1000 Hz");
  EXPECT_EQ(w.data.channels(), (std::vector<std::string>{"susp_defl_fl_m"}));
}

TEST(GenerateLabDense, BadSettingsNameTheField) {
  const Study& s = demo();
  struct Case {
    std::function<void(LabOptions&)> set;
    std::string expect;
  };
  const std::vector<Case> cases = {
      {[](LabOptions& o) { o.rate_hz = 300.0; },
       "lab.rate_hz: must divide the output rate 1000 Hz into an integer step"},
      {[](LabOptions& o) { o.rate_hz = 2000.0; }, "lab.rate_hz: must divide"},
      {[](LabOptions& o) { o.rate_hz = -5.0; }, "lab.rate_hz: must divide"},
      {[](LabOptions& o) { o.window = std::make_pair(1.2, 0.9); },
       "lab.window: expects T0,T1 with T0 < T1"},
      {[](LabOptions& o) { o.window = std::make_pair(0.0, 9.0); },
       "lab.window: 0 .. 9 s lies outside the scenario 'diag_bump'"},
      {[](LabOptions& o) { o.channels = {"hub_force_fl_kN"}; }, "lab.channels: wrong unit suffix"},
      {[](LabOptions& o) {
         o.channels = {"susp_defl_fl_m", "susp_defl_fl_m"};
       },
       "lab.channels: channel 'susp_defl_fl_m' listed twice"},
      {[](LabOptions& o) { o.times_mode = LabTimesMode::Study, o.rate_hz = 200.0; },
       "lab.rate_hz: needs every sample kept (times mode all)"},
      {[](LabOptions& o) {
         o.times_mode = LabTimesMode::Study, o.window = std::make_pair(0.9, 1.2);
       },
       "lab.window: needs every sample kept (times mode all)"},
      {[](LabOptions& o) {
         o.hidden_effects = {EffectSetting{"bump_stop", {}}, EffectSetting{"bump_stop", {}}};
       },
       "lab.hidden_effects: effect bump_stop given twice"},
      {[](LabOptions& o) { o.hidden_effects = {hidden("bump_stop:stiffnes=1")}; },
       "--hidden-effect stiffnes: unknown parameter 'bump_stop.stiffnes'"},
      {[](LabOptions& o) { o.hidden_effects = {hidden("bump_stop:gap_m=-1")}; },
       "--hidden-effect gap_m: bump_stop.gap_m"},
  };
  for (const auto& c : cases) {
    LabOptions o = denseBump();
    c.set(o);
    try {
      generateLab(s, s.assemblies().front(), o);
      ADD_FAILURE() << "no error for " << c.expect;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(hidden("bump_stopp"), InputError);
}

TEST(GenerateFieldHidden, HiddenEffectChangesFieldData) {
  const Study& s = demo();
  FieldOptions opt;
  opt.scenario = "diag_rough";
  opt.runs = 2;
  opt.threads = 2;
  opt.t_begin_s = 0.0;
  opt.t_end_s = 3.0;
  const FieldResult base = generateField(s, s.assemblies().front(), opt);
  opt.hidden_effects = {hidden("damper_asymmetry:ratio=2.5")};
  const FieldResult hid = generateField(s, s.assemblies().front(), opt);
  ASSERT_EQ(base.data.values.size(), hid.data.values.size());
  EXPECT_EQ(base.data.road_seeds, hid.data.road_seeds) << "the same roads";
  double diff = 0;
  for (std::size_t i = 0; i < base.data.values.size(); ++i)
    diff = std::max(diff, std::abs(base.data.values[i] - hid.data.values[i]));
  EXPECT_GT(diff, 200.0) << "rebound damping x2.5 on a class-C road";
  ASSERT_TRUE(hid.provenance.contains("hidden_effects"));
  EXPECT_EQ(hid.provenance["hidden_effects"][0]["name"], "damper_asymmetry");
  EXPECT_EQ(hid.provenance["hidden_effects"][0]["parameters"]["ratio"].get<double>(), 2.5);
  EXPECT_FALSE(base.provenance.contains("hidden_effects"));
}

// Lab files of two scenarios made with one seed carry independent noise (the stream depends on
// the scenario): with one stream the same sequence went into both, and a diagnosis pooling them
// counted it twice.
TEST(GenerateLabDense, TwoScenariosWithOneSeedHaveIndependentNoise) {
  const Study& s = demo();
  std::vector<std::vector<double>> noise;
  for (const std::string sc : {"diag_bump", "diag_rough"}) {
    LabOptions o = denseBump();
    o.scenario = sc;
    o.repetitions = 1;
    o.rate_hz = 200.0;
    o.channels = {"hub_force_fl_N"};
    o.seed = 5;
    const LabResult r = generateLab(s, s.assemblies().front(), o);
    const auto& clean = r.noise_free.column("hub_force_fl_N");
    const auto& t = r.noise_free.column("time_s");
    std::vector<double> e;
    for (const auto& rec : r.data.records) {
      const auto k = static_cast<std::size_t>(
          std::lower_bound(t.begin(), t.end(), rec.time_s - 1e-9) - t.begin());
      ASSERT_LT(k, t.size());
      e.push_back(rec.value - clean[k]);
    }
    noise.push_back(e);
  }
  ASSERT_EQ(noise[0].size(), noise[1].size());
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < noise[0].size(); ++i) {
    sab += noise[0][i] * noise[1][i];
    saa += noise[0][i] * noise[0][i];
    sbb += noise[1][i] * noise[1][i];
  }
  // 601 samples each: the correlation of independent sequences has sd 0.04.
  EXPECT_LT(std::abs(sab / std::sqrt(saa * sbb)), 0.2);
  EXPECT_NEAR(std::sqrt(saa / static_cast<double>(noise[0].size())), std::sqrt(s.noise_variance_N2),
              0.1 * std::sqrt(s.noise_variance_N2));
}
