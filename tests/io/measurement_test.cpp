// Measurement files (io/measurement.hpp): the tidy lab layout and the field matrix. Round trips
// are exact; every rule of the readers gives one line naming file:line, the field and the rule.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "common/errors.hpp"
#include "io/measurement.hpp"

using namespace dtwin;

namespace {

std::string labError(const std::string& text) {
  try {
    parseLabCsv(text, "lab.csv");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    return e.what();
  }
  return "(no error)";
}

std::string fieldError(const std::string& text) {
  try {
    parseFieldCsv(text, "field.csv");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    return e.what();
  }
  return "(no error)";
}

const std::string H = "repetition,time_s,channel,value\n";

LabData sample() {
  LabData d;
  for (long rep = 1; rep <= 3; ++rep)
    for (const char* ch : {"hub_force_fl_N", "susp_defl_fl_m"})
      for (double t : {6.005, 6.1, 7.25})
        d.records.push_back({rep, t, ch,
                             (std::string(ch) == "hub_force_fl_N" ? 1000.0 : 0.01) *
                                 (std::sqrt(2.0) * rep + t / 3000.0)});
  d.records.push_back({4, 0.0, "chassis_pitch_acc_radps2", 1e-300});
  d.records.push_back({4, 0.1 + 0.2, "chassis_pitch_acc_radps2", -0.1});
  return d;
}

}  // namespace

TEST(LabCsv, RoundTripIsExact) {
  const LabData d = sample();
  const std::string text = labCsvText(d);
  EXPECT_EQ(text.substr(0, H.size()), H);
  EXPECT_NE(text.find("\n1,6.005,hub_force_fl_N,"), std::string::npos) << text;
  const LabData back = parseLabCsv(text, "mem.csv");
  ASSERT_EQ(back.records.size(), d.records.size());
  for (std::size_t i = 0; i < d.records.size(); ++i) {
    EXPECT_EQ(back.records[i].repetition, d.records[i].repetition);
    EXPECT_EQ(back.records[i].time_s, d.records[i].time_s);  // bit-exact
    EXPECT_EQ(back.records[i].channel, d.records[i].channel);
    EXPECT_EQ(back.records[i].value, d.records[i].value);
  }
  EXPECT_EQ(back.channels(), (std::vector<std::string>{"hub_force_fl_N", "susp_defl_fl_m",
                                                       "chassis_pitch_acc_radps2"}));
  EXPECT_EQ(back.repetitions(), (std::vector<long>{1, 2, 3, 4}));
  EXPECT_EQ(back.times("hub_force_fl_N"), (std::vector<double>{6.005, 6.1, 7.25}));

  const std::string path = ::testing::TempDir() + "/measurement/lab.csv";
  writeLabCsv(path, d);
  EXPECT_EQ(readLabCsv(path).records.size(), d.records.size());
}

TEST(LabCsv, ValuesOutsideTheirUnitsPlausibleRangeAreRefused) {
  // Finite, yet no road vehicle measures them: 2 MN at a hub, 11 m of strut deflection.
  EXPECT_NE(labError(H + "1,6.0,hub_force_fl_N,2e6\n")
                .find("lab.csv:2: value: must lie in the plausible range [-1e+06, 1e+06] N"),
            std::string::npos);
  EXPECT_NE(labError(H + "1,6.0,susp_defl_fl_m,-11\n").find("[-10, 10] m for susp_defl_fl_m"),
            std::string::npos);
  EXPECT_EQ(labError(H + "1,6.0,hub_force_fl_N,-9.99e5\n"), "(no error)");
  EXPECT_NE(labError(H + "1,2e6,hub_force_fl_N,1\n").find("time_s: must be <= 1e+06 s"),
            std::string::npos);
  EXPECT_NE(fieldError("run,t_1.0\n1,1e13\n").find("plausible range of any channel"),
            std::string::npos);
}

TEST(LabCsv, AcceptsWhatSpreadsheetsWrite) {
  // BOM, CRLF, columns in another order, quotes, spaces, blank lines, interleaved channels.
  const std::string text =
      "\xEF\xBB\xBF\"channel\",time_s , value,repetition\r\n"
      "hub_force_fl_N,6.1,4000.5,1\r\n"
      "\r\n"
      "\"susp_defl_fl_m\", 6.1 ,+0.01,1\r\n"
      "hub_force_fl_N,6.2,3900,1\r\n"
      "hub_force_fl_N,6.1,4100,2\r\n";
  const LabData d = parseLabCsv(text, "x.csv");
  ASSERT_EQ(d.records.size(), 4u);
  EXPECT_EQ(d.records[1].channel, "susp_defl_fl_m");
  EXPECT_DOUBLE_EQ(d.records[1].value, 0.01);
  EXPECT_EQ(d.records[3].repetition, 2);
}

TEST(LabCsv, EveryRuleHasItsMessage) {
  struct Case {
    std::string text, expect;
  };
  const std::string ok = "1,6.1,hub_force_fl_N,4000\n";
  std::string seventeen = H;  // lines 2..16 fine, line 17 goes back in time
  for (int i = 0; i < 15; ++i)
    seventeen += "3," + formatExact((52 + i) / 10.0) + ",hub_force_fl_N,4000\n";
  seventeen += "3,6.5,hub_force_fl_N,4000\n";
  const std::vector<Case> cases = {
      {"", "lab.csv: empty file (expected the header repetition,time_s,channel,value)"},
      {"\n  \n", "lab.csv: empty file (expected the header repetition,time_s,channel,value)"},
      {H, "lab.csv: no records after the header (line 1)"},
      {"repetition,time_s,channel\n" + ok,
       "lab.csv:1: header: missing column 'value'; expected exactly "
       "repetition,time_s,channel,value"},
      {"repetition,time_s,channel,value,unit\n" + ok,
       "lab.csv:1: header: unexpected column 'unit'; expected exactly "
       "repetition,time_s,channel,value"},
      {"repetition,time,channel,value\n" + ok,
       "lab.csv:1: header: unexpected column 'time' (did you mean 'time_s'?); expected exactly "
       "repetition,time_s,channel,value"},
      {"repetition,time_s,channel,value,value\n" + ok,
       "lab.csv:1: header: column 'value' appears twice"},
      {H + ok + "1,6.2,hub_force_fl_N,4000,7\n",
       "lab.csv:3: expected 4 fields (repetition,time_s,channel,value), got 5"},
      {H + "1,6.2,hub_force_fl_N\n",
       "lab.csv:2: expected 4 fields (repetition,time_s,channel,value), got 3"},
      {H + "0,6.1,hub_force_fl_N,4000\n",
       "lab.csv:2: repetition: must be a positive integer, got '0'"},
      {H + "-2,6.1,hub_force_fl_N,4000\n",
       "lab.csv:2: repetition: must be a positive integer, got '-2'"},
      {H + "1.5,6.1,hub_force_fl_N,4000\n",
       "lab.csv:2: repetition: must be a positive integer, got '1.5'"},
      {H + ",6.1,hub_force_fl_N,4000\n",
       "lab.csv:2: repetition: must be a positive integer, got ''"},
      {H + "1,six,hub_force_fl_N,4000\n",
       "lab.csv:2: time_s: must be a number (seconds), got 'six'"},
      {H + "1,nan,hub_force_fl_N,4000\n", "lab.csv:2: time_s: must be finite, got nan"},
      {H + "1,-0.5,hub_force_fl_N,4000\n",
       "lab.csv:2: time_s: must be >= 0 (seconds since the scenario start), got -0.5"},
      {seventeen,
       "lab.csv:17: time_s: not increasing for repetition 3 channel hub_force_fl_N (6.5 after "
       "6.6)"},
      {H + ok + "1,6.1,hub_force_fl_N,4001\n",
       "lab.csv:3: time_s: repeated for repetition 1 channel hub_force_fl_N (6.1 after 6.1)"},
      {H + "1,6.1,hub_forc_fl_N,4000\n",
       "lab.csv:2: channel: unknown channel 'hub_forc_fl_N' (did you mean 'hub_force_fl_N'?)"},
      {H + "1,6.1,hub_force_fl_kN,4\n",
       "lab.csv:2: channel: wrong unit suffix '_kN' for hub_force_fl: values must be in N, named "
       "'hub_force_fl_N'"},
      {H + "1,6.1,susp_defl_fl_mm,4\n",
       "lab.csv:2: channel: wrong unit suffix '_mm' for susp_defl_fl: values must be in m, named "
       "'susp_defl_fl_m'"},
      {H + "1,6.1,time_s,4\n", "lab.csv:2: channel: unknown channel 'time_s'"},
      {H + "1,6.1,,4\n",
       "lab.csv:2: channel: is empty (expected a channel name with its unit suffix, e.g. "
       "hub_force_fl_N)"},
      {H + "1,6.1,hub_force_fl_N,inf\n", "lab.csv:2: value: must be finite, got inf"},
      {H + "1,6.1,hub_force_fl_N,4 000\n", "lab.csv:2: value: must be a number, got '4 000'"},
      {H + "1,6.1,hub_force_fl_N,\n", "lab.csv:2: value: must be a number, got ''"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string e = labError(c.text);
    EXPECT_EQ(e.substr(0, c.expect.size()), c.expect);
  }
  try {
    readLabCsv("/nonexistent/lab.csv");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/lab.csv: cannot be read");
  }
}

TEST(LabCsv, InMemoryDataIsValidatedBeforeWriting) {
  LabData d = sample();
  d.records[2].time_s = 6.0;  // before 6.1 of the record above
  try {
    labCsvText(d);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        "lab data:4: time_s: not increasing for repetition 1 channel hub_force_fl_N (6 after 6.1)");
  }
  d = sample();
  d.records[0].value = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validateLabData(d, "x"), InputError);
  EXPECT_THROW(validateLabData(LabData{}, "x"), InputError);
}

TEST(FieldCsv, RoundTripIsExact) {
  FieldData d;
  for (int k = 0; k <= 10; ++k) d.times_s.push_back(static_cast<double>(10000 + k) / 1000.0);
  d.runs = {1, 2, 3};
  d.road_seeds = {0, 9007199254740991ULL, 18446744073709551615ULL};
  for (std::size_t i = 0; i < 3 * d.times_s.size(); ++i)
    d.values.push_back(std::sin(static_cast<double>(i)) * 4000.0 + 0.1);
  const std::string text = fieldCsvText(d);
  EXPECT_EQ(text.substr(0, 40), "run,road_seed,t_10.000,t_10.001,t_10.002");
  const FieldData b = parseFieldCsv(text, "f.csv");
  EXPECT_EQ(b.times_s, d.times_s);
  EXPECT_EQ(b.runs, d.runs);
  EXPECT_EQ(b.road_seeds, d.road_seeds);
  EXPECT_EQ(b.values, d.values);  // bit-exact

  FieldData m = d;  // measured data: no seeds
  m.road_seeds.clear();
  m.times_s = {0.5, 1.0, 1.25};
  m.values.resize(9);
  const std::string mt = fieldCsvText(m);
  EXPECT_EQ(mt.substr(0, mt.find('\n')), "run,t_0.50,t_1.00,t_1.25");
  const FieldData mb = parseFieldCsv(mt, "m.csv");
  EXPECT_TRUE(mb.road_seeds.empty());
  EXPECT_EQ(mb.times_s, m.times_s);

  const std::string path = ::testing::TempDir() + "/measurement/field.csv";
  writeFieldCsv(path, d);
  EXPECT_EQ(readFieldCsv(path).values, d.values);
}

TEST(FieldCsv, EveryRuleHasItsMessage) {
  struct Case {
    std::string text, expect;
  };
  const std::string h = "run,road_seed,t_10.000,t_10.001\n";
  const std::vector<Case> cases = {
      {"", "field.csv: empty file (expected the header run,road_seed,t_<seconds>,...)"},
      {"repetition,t_1\n1,2\n",
       "field.csv:1: header: first column must be 'run', got 'repetition'"},
      {"run,road_seed\n1,2\n",
       "field.csv:1: header: no time columns 't_<seconds>' after run,road_seed"},
      {"run,road_seed,10.0\n1,2,3\n",
       "field.csv:1: header: column 3 must be a time column 't_<seconds>' (e.g. t_10.000), got "
       "'10.0'"},
      {"run,t_1,t_0.5\n1,2,3\n",
       "field.csv:1: header: column 't_0.5': times must increase from column to column (0.5 after "
       "1)"},
      {"run,t_inf\n1,2\n", "field.csv:1: header: column 't_inf': time must be finite and >= 0"},
      {h, "field.csv: no runs after the header"},
      {h + "1,5,3\n", "field.csv:2: expected 4 fields (one per header column), got 3"},
      {h + "0,5,3,4\n", "field.csv:2: run: must be a positive integer, got '0'"},
      {h + "1,5,3,4\n1,6,3,4\n", "field.csv:3: run: run 1 appears twice"},
      {h + "1,-5,3,4\n", "field.csv:2: road_seed: must be an integer in [0, 2^64), got '-5'"},
      {h + "1,18446744073709551616,3,4\n",
       "field.csv:2: road_seed: must be an integer in [0, 2^64), got '18446744073709551616'"},
      {h + "1,5,3,x\n", "field.csv:2: t_10.001: must be a number, got 'x'"},
      {h + "1,5,nan,4\n", "field.csv:2: t_10.000: must be finite, got nan"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string e = fieldError(c.text);
    EXPECT_EQ(e.substr(0, c.expect.size()), c.expect);
  }
}
