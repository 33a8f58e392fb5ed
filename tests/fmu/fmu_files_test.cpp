// The parts of `twin export-fmu` that need no simulation: the zip archive (written and read back,
// its CRC checked), the FMI 2.0 rules of modelDescription.xml (the legal combinations of
// causality, variability and initial; unique names) and the FMI 2.0 schema check of a written
// description with xmllint, and the road fed from inputs (twin/input_road.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/errors.hpp"
#include "io/fmi_description.hpp"
#include "io/zip_archive.hpp"
#include "test_util.hpp"
#include "twin/input_road.hpp"

namespace fs = std::filesystem;
using namespace dtwin;

TEST(FmuFiles, ZipArchiveRoundTripsItsMembers) {
  std::string big(100000, 'a');
  for (std::size_t i = 0; i < big.size(); i += 7) big[i] = static_cast<char>('a' + i % 26);
  std::string binary;
  for (int i = 0; i < 256; ++i) binary.push_back(static_cast<char>(i));
  const std::vector<ZipMember> in = {{"modelDescription.xml", "<x/>"},
                                     {"binaries/", ""},
                                     {"binaries/linux64/a.so", binary},
                                     {"resources/big.txt", big},
                                     {"resources/empty", ""}};
  const std::string bytes = zipArchive(in);
  EXPECT_LT(bytes.size(), big.size() / 2) << "the repetitive member is deflated";
  const auto out = readZipArchive(bytes, "test.zip");
  ASSERT_EQ(out.size(), in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_EQ(out[i].name, in[i].name);
    EXPECT_EQ(out[i].data, in[i].data) << in[i].name;
  }
  EXPECT_EQ(zipArchive(in), bytes) << "the same members give the same bytes";
  // unzip(1)'s own reader agrees, when it is installed.
  const fs::path d = dtwin_test::freshDir("fmu_zip");
  dtwin_test::writeText(d / "a.zip", bytes);
  if (std::system("command -v unzip > /dev/null 2>&1") == 0) {
    EXPECT_EQ(std::system(("unzip -tq '" + (d / "a.zip").string() + "' > /dev/null").c_str()), 0);
  }
}

TEST(FmuFiles, ZipArchiveRefusesDamageAndBadNames) {
  std::string bytes = zipArchive({{"a.txt", std::string(5000, 'x') + "tail"}});
  EXPECT_THROW(readZipArchive(bytes.substr(0, 10), "t.zip"), InputError);
  // A flipped byte in the deflated data: inflating fails or the CRC does not match.
  bytes[40] = static_cast<char>(bytes[40] ^ 0x55);
  EXPECT_THROW(readZipArchive(bytes, "t.zip"), InputError);
  EXPECT_THROW(zipArchive({{"../up", "x"}}), InputError);
  EXPECT_THROW(zipArchive({{"/abs", "x"}}), InputError);
  EXPECT_THROW(zipArchive({{"a", "x"}, {"a", "y"}}), InputError);
  EXPECT_THROW(zipArchive({{"", "x"}}), InputError);
}

TEST(FmuFiles, DescriptionRulesFollowFmi2Table) {
  auto rule = [](const char* c, const char* v, const char* i, bool start) {
    FmiVariable x;
    x.name = "x";
    x.causality = c;
    x.variability = v;
    x.initial = i;
    if (start) x.start = 1.0;
    return fmi2CombinationRule(x);
  };
  EXPECT_EQ(rule("parameter", "fixed", "exact", true), "");
  EXPECT_EQ(rule("input", "continuous", "", true), "");
  EXPECT_EQ(rule("output", "continuous", "", false), "");
  EXPECT_EQ(rule("output", "continuous", "calculated", false), "");
  EXPECT_NE(rule("parameter", "continuous", "exact", true), "");  // not a legal pair
  EXPECT_NE(rule("input", "fixed", "", true), "");
  EXPECT_NE(rule("parameter", "fixed", "calculated", true), "");    // initial not allowed
  EXPECT_NE(rule("input", "continuous", "exact", true), "");        // inputs take no initial
  EXPECT_NE(rule("parameter", "fixed", "exact", false), "");        // exact needs a start
  EXPECT_NE(rule("input", "continuous", "", false), "");            // inputs need a start
  EXPECT_NE(rule("output", "continuous", "calculated", true), "");  // calculated: no start
}

namespace {
FmiModelInfo smallModel() {
  FmiModelInfo m;
  m.model_name = "t & <model>";
  m.model_identifier = "t_model";
  m.guid = "{123}";
  m.generation_tool = "test";
  m.generation_time_utc = "2026-01-01T00:00:00Z";
  m.variables = {{"in_speed_mps", "input", "continuous", "", 0.0, "m/s", "speed"},
                 {"hub_force_fl_N", "output", "continuous", "", std::nullopt, "N", "force \"fl\""},
                 {"tire.stiffness", "parameter", "fixed", "exact", 2e5, "N/m", "k"}};
  return m;
}
}  // namespace

TEST(FmuFiles, DescriptionPassesTheFmi2Schema) {
  const std::string xml = fmi2ModelDescription(smallModel());
  EXPECT_NE(xml.find("valueReference=\"3\""), std::string::npos);
  EXPECT_NE(xml.find("t &amp; &lt;model&gt;"), std::string::npos) << "escaped";
  EXPECT_NE(xml.find("<Unknown index=\"2\"/>"), std::string::npos) << "the output's structure";
  const fs::path d = dtwin_test::freshDir("fmu_description");
  dtwin_test::writeText(d / "modelDescription.xml", xml);
  const std::string xsd =
      std::string(DTWIN_SOURCE_DIR) + "/third_party/reference-fmus/schema/fmi2Merged.xsd";
  const std::string cmd = "xmllint --noout --schema '" + xsd + "' '" +
                          (d / "modelDescription.xml").string() + "' 2> '" +
                          (d / "log.txt").string() + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << dtwin_test::slurp(d / "log.txt");
  // The same check fails on a description the schema refuses (it is a real check).
  std::string bad = xml;
  bad.replace(bad.find("causality=\"input\""), 17, "causality=\"inputs\"");
  dtwin_test::writeText(d / "bad.xml", bad);
  EXPECT_NE(std::system(("xmllint --noout --schema '" + xsd + "' '" + (d / "bad.xml").string() +
                         "' 2> /dev/null")
                            .c_str()),
            0);
}

TEST(FmuFiles, DescriptionRefusesRepeatedNamesAndIllegalCombinations) {
  FmiModelInfo m = smallModel();
  m.variables.push_back(m.variables[0]);
  EXPECT_THROW(fmi2ModelDescription(m), InputError);
  m = smallModel();
  m.variables[2].variability = "continuous";
  try {
    fmi2ModelDescription(m);
    FAIL() << "a continuous parameter was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tire.stiffness"), std::string::npos) << e.what();
  }
}

TEST(FmuFiles, InputRoadInterpolatesAndContinuesItsSamples) {
  InputRoad r;
  EXPECT_EQ(r.sampleAt(0, 5.0).height_m, 0.0) << "no sample: flat";
  r.push(0, 0.0, 0.01);
  EXPECT_EQ(r.sampleAt(0, -3.0).height_m, 0.01) << "held before the first sample";
  EXPECT_EQ(r.sampleAt(0, 3.0).height_m, 0.01) << "one sample: held";
  r.push(0, 1.0, 0.03);
  r.push(0, 2.0, 0.02);
  EXPECT_NEAR(r.sampleAt(0, 0.5).height_m, 0.02, 1e-15);
  EXPECT_NEAR(r.sampleAt(0, 0.5).slope, 0.02, 1e-15);
  EXPECT_NEAR(r.sampleAt(0, 3.0).height_m, 0.01, 1e-15) << "continued along the last slope";
  EXPECT_NEAR(r.sampleAt(0, 3.0).slope, -0.01, 1e-15);
  // The integral is the interpolant's: trapezoids between the samples.
  EXPECT_NEAR(r.integralAt(0, 2.0) - r.integralAt(0, 0.0), 0.02 + 0.025, 1e-15);
  EXPECT_NEAR(r.integralAt(0, 1.5) - r.integralAt(0, 0.5),
              0.5 * (0.02 + 0.03) * 0.5 + 0.5 * (0.03 + 0.025) * 0.5, 1e-15);
  // A standing wheel: the same distance replaces the height.
  r.push(0, 2.0, 0.04);
  EXPECT_EQ(r.size(0), 3u);
  EXPECT_NEAR(r.sampleAt(0, 2.0).height_m, 0.04, 1e-15);
  // The corners are apart; a track reads its front wheel.
  r.push(3, -2.7, -0.05);
  EXPECT_EQ(r.sampleAt(3, 0.0).height_m, -0.05);
  EXPECT_EQ(r.sampleAt(1, 0.0).height_m, 0.0);
  EXPECT_NEAR(r.sample(Track::Left, 0.5).height_m, 0.02, 1e-15);
}
