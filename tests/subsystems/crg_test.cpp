// OpenCRG road files (subsystems/crg.hpp): known answers from files written here (a plane, a sine
// along u, banking, slope), the heights at the nodes bit for bit the file's, the C API's holds
// outside the grid, its NaN filling, binary data, and bad files refused in one line naming the file
// and the line or keyword.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "subsystems/crg.hpp"
#include "test_util.hpp"

using namespace dtwin;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A 10-character LRFI field.
std::string field10(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%10.7f", x);
  return std::string(b).substr(0, 10);
}

/// The text of an LRFI file with `rows` cross sections from u0 by du and long sections at `v`
/// (explicit "long section at v = X" channels), heights z(u, v); `extra_channels` (D: lines)
/// come first with their values from `extra(k)` (one per channel).
struct CrgSpec {
  double u0 = 0.0, du = 0.5;
  int rows = 21;
  std::vector<double> v = {-1.0, -0.5, 0.0, 0.5, 1.0};
  std::function<double(double, double)> z = [](double, double) { return 0.0; };
  std::vector<std::string> extra_channels;
  std::function<std::vector<double>(int)> extra = [](int) { return std::vector<double>{}; };
  std::string road_extra;  ///< more $ROAD_CRG lines
  std::string sections;    ///< more sections before $KD_Definition
  std::string format = "LRFI";
  bool end_u = true;
};

std::string crgText(const CrgSpec& s) {
  std::string t = "$CT\nwritten by crg_test\n$\n";
  t += s.sections;
  t += "$ROAD_CRG\nREFERENCE_LINE_START_U = " + std::to_string(s.u0) +
       "\nREFERENCE_LINE_INCREMENT = " + std::to_string(s.du) + "   ! comment\n";
  if (s.end_u) t += "REFERENCE_LINE_END_U = " + std::to_string(s.u0 + s.du * (s.rows - 1)) + "\n";
  t += s.road_extra + "$!****\n$KD_Definition\n#:" + s.format + "\nU:reference line u,m,0,1\n";
  for (const auto& c : s.extra_channels) t += "D:" + c + "\n";
  for (double v : s.v) t += "D:long section at v = " + std::to_string(v) + ",m\n";
  t += "$\n* a comment\n$$$$$$$$10$$$$$$$$20\n";
  for (int k = 0; k < s.rows; ++k) {
    std::vector<double> vals = s.extra(k);
    const double u = s.u0 + s.du * k;
    for (double v : s.v) vals.push_back(s.z(u, v));
    std::string line;
    for (std::size_t i = 0; i < vals.size(); ++i) {
      line += std::isnan(vals[i]) ? std::string("*missing*") + " " : field10(vals[i]);
      if (i % 8 == 7 || i + 1 == vals.size()) {
        t += line + "\n";
        line.clear();
      }
    }
  }
  return t;
}

/// The InputError's text of parsing `text`, "" when it parses.
std::string errorOf(const std::string& text, const std::string& name = "road.crg") {
  try {
    parseCrg(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectRefused(const std::string& text, const std::string& where, const std::string& rule) {
  const std::string e = errorOf(text);
  ASSERT_FALSE(e.empty()) << "not refused; wanted " << rule;
  EXPECT_EQ(e.rfind(where, 0), 0u) << e;
  EXPECT_NE(e.find(rule), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

}  // namespace

TEST(Crg, APlaneIsExactAnywhereInsideOnBothTracks) {
  // z = a + b u + c v: decimal node values (written exactly with 7 decimals), so the bilinear
  // surface is the plane itself; the C API's reference point (u0, rightmost v) sits at z = 0.
  const double a = 0.01, b = 0.002, c = 0.004;
  CrgSpec spec;
  spec.z = [&](double u, double v) { return a + b * u + c * v; };
  const CrgSurface s = parseCrg(crgText(spec), "plane.crg");
  ASSERT_EQ(s.rows, 21u);
  ASSERT_EQ(s.v_m.size(), 5u);
  EXPECT_EQ(s.format, "LRFI");
  const double off = -(a + c * -1.0);
  EXPECT_NEAR(s.z_offset_m, off, 1e-15);
  for (double u = 0.0; u <= 10.0; u += 0.173)
    for (double v = -1.0; v <= 1.0; v += 0.11)
      EXPECT_NEAR(s.height(u, v), a + b * u + c * v + off, 1e-12) << u << " " << v;
  // The road's tracks at v = +/-0.8: the nodes are the surface's heights, and between them the
  // C1 interpolant of a straight line is the line.
  const auto road = makeCrgRoad(s, 0.8, -0.8, 0.0, {{"type", "crg"}});
  for (double x = 0.0; x <= 10.0; x += 0.0371) {
    EXPECT_NEAR(road->sample(Track::Left, x).height_m, a + b * x + c * 0.8 + off, 1e-12);
    EXPECT_NEAR(road->sample(Track::Right, x).height_m, a + b * x - c * 0.8 + off, 1e-12);
    EXPECT_NEAR(road->sample(Track::Left, x).slope, b, 1e-11);
  }
  EXPECT_LT(road->describe().at("c1_vs_bilinear_bound_m").get<double>(), 1e-15);
}

TEST(Crg, TheNodesAreTheFilesNumbersBitForBit) {
  // A sine along u that varies across v; z(u0, v_right) = 0, so no shift: the nodes are the
  // file's decimal numbers as strtod reads them.
  CrgSpec spec;
  spec.du = 0.1;
  spec.rows = 101;
  spec.z = [](double u, double v) { return 0.01 * std::sin(2 * kPi * u / 2.5) * (1.3 + v); };
  const std::string text = crgText(spec);
  const CrgSurface s = parseCrg(text, "sine.crg");
  EXPECT_EQ(s.z_offset_m, 0.0);
  for (std::size_t k = 0; k < s.rows; ++k)
    for (std::size_t j = 0; j < s.v_m.size(); ++j) {
      const double file = std::strtod(field10(spec.z(0.1 * k, spec.v[j])).c_str(), nullptr);
      EXPECT_EQ(s.gridHeight(k, j), file);
      EXPECT_EQ(s.nodeHeight(k, s.v_m[j]), file) << k << " " << j;
      // At u = u0 + k du the fraction may come out a rounding below 1 (as in the C API).
      EXPECT_NEAR(s.height(s.u0_m + s.du_m * k, s.v_m[j]), file, 1e-15) << k << " " << j;
    }
  // Tracks on long sections: the road's node heights are the file's numbers; between the nodes
  // the C1 interpolant stays within its stated bound of the C API's bilinear surface.
  const auto road = makeCrgRoad(s, 0.5, -0.5, 0.0, {{"type", "crg"}});
  for (std::size_t k = 0; k < s.rows; ++k) {
    EXPECT_EQ(road->heights(Track::Left)[k], s.gridHeight(k, 3));
    EXPECT_EQ(road->heights(Track::Right)[k], s.gridHeight(k, 1));
    EXPECT_NEAR(road->sample(Track::Left, s.du_m * k).height_m, s.gridHeight(k, 3), 1e-15) << k;
  }
  const double bound = road->describe().at("c1_vs_bilinear_bound_m").get<double>();
  EXPECT_GT(bound, 0.0);
  double worst = 0.0;
  for (double x = 0.0; x <= 10.0; x += 0.00731) {
    const double d = std::abs(road->sample(Track::Left, x).height_m - s.height(x, 0.5));
    worst = std::max(worst, d);
    EXPECT_LE(d, bound + 1e-15) << x;
    EXPECT_NEAR(road->sample(Track::Left, x).height_m, 0.01 * std::sin(2 * kPi * x / 2.5) * 1.8,
                2e-5)
        << x;
  }
  EXPECT_GT(worst, 0.05 * bound);  // the bound is not vacuous
}

TEST(Crg, OutsideTheGridTheBordersAreHeld) {
  CrgSpec spec;
  spec.u0 = 100.0;
  spec.z = [](double u, double v) { return 0.001 * (u - 100.0) + 0.002 * v * v; };
  const CrgSurface s = parseCrg(crgText(spec), "held.crg");
  EXPECT_DOUBLE_EQ(s.u1_m(), 110.0);
  for (double v : {-1.0, -0.3, 0.7}) {
    EXPECT_EQ(s.height(90.0, v), s.height(100.0, v));
    EXPECT_EQ(s.height(99.999, v), s.height(100.0, v));
    EXPECT_EQ(s.height(125.0, v), s.height(110.0, v));
  }
  for (double u : {100.0, 103.7, 110.0}) {
    EXPECT_EQ(s.height(u, 3.0), s.height(u, 1.0));
    EXPECT_EQ(s.height(u, -7.0), s.height(u, -1.0));
  }
  // The road: x = u - 100; held flat before and after.
  const auto road = makeCrgRoad(s, 0.5, -0.5, 100.0, {{"type", "crg"}});
  EXPECT_DOUBLE_EQ(road->extent().lo, 0.0);
  EXPECT_DOUBLE_EQ(road->extent().hi, 10.0);
  EXPECT_EQ(road->sample(Track::Left, -3.0).height_m, s.height(100.0, 0.5));
  EXPECT_EQ(road->sample(Track::Left, 13.0).height_m, s.height(110.0, 0.5));
  EXPECT_EQ(road->sample(Track::Left, -3.0).slope, 0.0);
}

TEST(Crg, BankingAndSlopeOfTheReferenceLine) {
  // A flat grid on a banked, sloped reference line: banking b(u) times v (v held at the
  // borders), plus the slope integrated as the C API does (z_k+1 = z_k + s_k+1 du).
  CrgSpec spec;
  spec.extra_channels = {"reference line banking,m/m", "reference line slope,m/m"};
  spec.extra = [](int k) { return std::vector<double>{0.02 + 0.001 * k, 0.05}; };
  const CrgSurface s = parseCrg(crgText(spec), "banked.crg");
  ASSERT_EQ(s.bank.size(), s.rows);
  auto bank = [](double u) { return 0.02 + 0.002 * u; };  // 0.001 per row of 0.5 m
  const double off = bank(0.0) * 1.0;                     // -(bank(0) * v_right), v_right = -1
  for (double u = 0.0; u <= 10.0; u += 0.37)
    for (double v = -2.0; v <= 2.0; v += 0.3) {
      const double vc = std::min(1.0, std::max(-1.0, v));
      EXPECT_NEAR(s.height(u, v), 0.05 * u + bank(u) * vc + off, 1e-12) << u << " " << v;
    }
  // A constant bank from the header alone (REFERENCE_LINE_START_B), and a constant slope
  // (REFERENCE_LINE_START_S) from REFERENCE_LINE_START_Z.
  CrgSpec header;
  header.road_extra =
      "REFERENCE_LINE_START_B = 0.03\nREFERENCE_LINE_START_S = -0.01\nREFERENCE_LINE_START_Z = "
      "5\n";
  const CrgSurface h = parseCrg(crgText(header), "header.crg");
  EXPECT_NEAR(h.height(4.0, 0.6), -0.01 * 4.0 + 0.03 * (0.6 + 1.0), 1e-12);
  EXPECT_NEAR(h.height(4.0, 1.6), -0.01 * 4.0 + 0.03 * (1.0 + 1.0), 1e-12);
}

TEST(Crg, MissingHeightsAreFilledAsTheCApiFillsThem) {
  CrgSpec spec;
  spec.rows = 3;
  spec.v = {-1.0, -0.5, 0.0, 0.5, 1.0};
  const double nan = std::nan("");
  const std::vector<std::vector<double>> z = {{nan, 0.1, 0.2, 0.3, nan},   // both borders
                                              {0.1, nan, nan, 0.4, 0.5},   // inside
                                              {nan, nan, 0.3, nan, nan}};  // one valid
  spec.z = [&](double u, double v) {
    return z[static_cast<int>(std::lround(u / 0.5))][static_cast<int>(std::lround((v + 1) / 0.5))];
  };
  const CrgSurface s = parseCrg(crgText(spec), "holes.crg");
  // Right of the first valid height: that one; elsewhere the nearest valid one to the right.
  const std::vector<std::vector<double>> want = {
      {0.1, 0.1, 0.2, 0.3, 0.3}, {0.1, 0.1, 0.1, 0.4, 0.5}, {0.3, 0.3, 0.3, 0.3, 0.3}};
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t j = 0; j < 5; ++j) EXPECT_EQ(s.gridHeight(k, j), want[k][j]) << k << j;
  EXPECT_EQ(s.nan_filled, 6u);
  EXPECT_EQ(s.nan_inside, 2u);
  // A cross section with no height at all is refused.
  spec.z = [&](double u, double) { return u == 0.5 ? nan : 0.0; };
  expectRefused(crgText(spec), "road.crg: ", "data row 2 (u = 0.5): every height is missing");
}

TEST(Crg, LongSectionsByNumberAndDoublePrecisionText) {
  // "long section N" channels placed by LONG_SECTION_V_RIGHT and _INCREMENT; LDFI: 20 characters
  // per number, 4 per line, a row wrapped over two lines.
  std::string t =
      "$CT\nx\n$\n$ROAD_CRG\nREFERENCE_LINE_INCREMENT = 2.0\nLONG_SECTION_V_RIGHT = -0.9\n"
      "LONG_SECTION_V_LEFT = 0.9\nLONG_SECTION_V_INCREMENT = 0.3\n$\n$KD_Definition\n#:LDFI\n";
  for (int n = 1; n <= 7; ++n) t += "D:long section " + std::to_string(n) + ",m\n";
  t += "$\n$$$$\n";
  for (int k = 0; k < 3; ++k) {
    for (int n = 0; n < 7; ++n) {
      char b[32];
      std::snprintf(b, sizeof b, "%20.12e", 0.001 * k + 0.0001 * n);
      t += b;
      if (n == 3 || n == 6) t += "\n";
    }
  }
  const CrgSurface s = parseCrg(t, "numbered.crg");
  ASSERT_EQ(s.v_m.size(), 7u);
  EXPECT_NEAR(s.v_m.front(), -0.9, 1e-15);
  EXPECT_NEAR(s.v_m.back(), 0.9, 1e-15);
  EXPECT_EQ(s.rows, 3u);
  EXPECT_EQ(s.gridHeight(0, 0), 0.0);
  EXPECT_EQ(s.gridHeight(2, 6), 2.6e-3);
}

TEST(Crg, BinaryDataBigEndian) {
  // KRBI: 4-byte big-endian floats, rows back to back; LDBI: 8-byte doubles in rows padded to
  // 80-byte records. The row count comes from START_U, END_U and INCREMENT.
  for (const std::string fmt : {"KRBI", "LDBI"}) {
    SCOPED_TRACE(fmt);
    const bool dbl = fmt[1] == 'D';
    std::string t =
        "$CT\nx\n$\n$ROAD_CRG\nREFERENCE_LINE_START_U = 1\nREFERENCE_LINE_END_U = 3\n"
        "REFERENCE_LINE_INCREMENT = 0.5\n$\n$KD_Definition\n#:" +
        fmt +
        "\nD:long section at v = -1,m\nD:long section at v = 0,m\nD:long section at v = 1,m\n"
        "$\n$$$$\n";
    std::vector<double> values;
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 3; ++j) values.push_back(0.125 * k - 0.25 * j + (dbl ? 1e-12 : 0.0));
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::uint64_t bits = 0;
      int size = dbl ? 8 : 4;
      if (dbl) {
        std::memcpy(&bits, &values[i], 8);
      } else {
        const float f = static_cast<float>(values[i]);
        std::uint32_t b32;
        std::memcpy(&b32, &f, 4);
        bits = b32;
      }
      for (int b = size - 1; b >= 0; --b) t += static_cast<char>((bits >> (8 * b)) & 0xff);
      if (dbl && i % 3 == 2) t += std::string(80 - 24, '\0');  // pad the row to 80 bytes
    }
    const CrgSurface s = parseCrg(t, "binary.crg");
    ASSERT_EQ(s.rows, 5u);
    for (std::size_t k = 0; k < 5; ++k)
      for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(s.gridHeight(k, j), values[k * 3 + j]);
    // One row short: refused.
    expectRefused(t.substr(0, t.size() - (dbl ? 80 : 12)), "road.crg: ",
                  "fewer than 5 rows of " + std::string(dbl ? "80" : "12") + " bytes");
  }
}

TEST(Crg, TheSamplesOfTheFormatParse) {
  // The layout of OpenCRG's handmade samples: wrapped rows, "**unused**" fields, fields that
  // touch ("0.0000000-0.0111111"), comments everywhere, lower-case keys, options that keep the
  // C API's defaults.
  const std::string t =
      "$CT                                                 ! comment text block\n"
      "CRG file example\n"
      "$!**********************************************************************\n"
      "$ROAD_CRG_OPTS\n* BORDER_MODE_U = 0\n  BORDER_MODE_U = 2  ! keep last\n"
      "warn_curv_local\t\t =  0.0000000000000000e+000\n$\n"
      "$ROAD_CRG                                          ! crg road parameters\n"
      "reference_line_start_u   = 0.0\nREFERENCE_LINE_END_U     = 2.0\n"
      "REFERENCE_LINE_INCREMENT = 1.0\nREFERENCE_LINE_START_PHI = 0.1\n"
      "LONG_SECTION_V_RIGHT     =-1.50\nLONG_SECTION_V_LEFT      = 1.50\n"
      "$!**********************************************************************\n"
      "$KD_Definition\n#:LRFI\nU:reference line u,m,0,1.0\n"
      "D:reference line phi,rad                                 ! heading angle\n"
      "D:reference line slope,m/m\n"
      "D:long section at v = -1.500,m\nD:long section at v = -1.000,m\n"
      "D:long section at v = -0.500,m\nD:long section at v =  0.000,m\n"
      "D:long section at v =  0.500,m\nD:long section at v =  1.000,m\n"
      "D:long section at v =  1.500,m\n"
      "$!**********************************************************************\n"
      "$$$$$$$$10$$$$$$$$20$$$$$$$$30$$$$$$$$40$$$$$$$$50$$$$$$$$60$$$$$$$$70$$$$$$$$80\n"
      "**unused****unused** 0.0000000 0.0000000 0.0000000 0.0000000 0.0000000 0.0000000\n"
      " 0.0000000\n"
      " 0.0000000 0.0110000 0.0000000 0.0000000 0.0111111 0.0111111 0.0111111 0.0000000\n"
      " 0.0000000\n"
      " 0.0000000 0.0110000 0.0000000 0.0000000 0.0111111 0.0000000 0.0000000-0.0111111\n"
      "-0.0111111\n";
  const CrgSurface s = parseCrg(t, "sample.crg");
  EXPECT_EQ(s.rows, 3u);
  EXPECT_TRUE(s.plan_geometry);
  EXPECT_EQ(s.gridHeight(1, 3), 0.0111111);
  EXPECT_EQ(s.gridHeight(2, 5), -0.0111111);
  EXPECT_EQ(s.gridHeight(2, 6), -0.0111111);
  EXPECT_NEAR(s.ref_z_m[2], 0.022, 1e-15);
  EXPECT_NEAR(s.height(2.0, 0.0), 0.022, 1e-15);
  EXPECT_NEAR(s.height(1.5, 0.0), 0.0165 + 0.5 * 0.0111111, 1e-15);
  // A byte-order mark and CRLF line ends change nothing.
  std::string crlf = "\xEF\xBB\xBF";
  for (char c : t) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const CrgSurface w = parseCrg(crlf, "windows.crg");
  EXPECT_EQ(w.z_m, s.z_m);
  EXPECT_EQ(w.ref_z_m, s.ref_z_m);
}

TEST(Crg, BadFilesAreRefusedInOneLineNamingTheFileAndLine) {
  CrgSpec good;
  good.z = [](double u, double v) { return 0.001 * u + 0.002 * v; };
  const std::string ok = crgText(good);
  ASSERT_EQ(errorOf(ok), "");
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string t = ok;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  // Missing $ROAD_CRG.
  {
    std::string t = ok;
    const auto a = t.find("$ROAD_CRG"), b = t.find("$KD_Definition");
    t.erase(a, b - a);
    expectRefused(t, "road.crg: ", "no $ROAD_CRG section");
  }
  // Increments inconsistent with the data count: END_U says 12 m, 21 rows of 0.5 m end at 10.
  expectRefused(replace("REFERENCE_LINE_END_U = 10.000000", "REFERENCE_LINE_END_U = 12"),
                "road.crg:7: ", "REFERENCE_LINE_END_U = 12 but 21 data rows");
  // A non-number in the data (line 19 is the third data row).
  {
    std::string t = ok;
    std::size_t at = t.find("$$$$");
    for (int i = 0; i < 3; ++i) at = t.find('\n', at) + 1;
    t.replace(at + 10, 10, "   abc    ");
    expectRefused(
        t, "road.crg:" + std::to_string(std::count(ok.begin(), ok.begin() + at, '\n') + 1) + ": ",
        "field 2 'abc' is not a number");
  }
  // Too few columns.
  {
    std::string t = ok;
    const std::size_t at = t.find('\n', t.find("$$$$")) + 1;
    t.erase(at + 30, 20);
    expectRefused(t, "road.crg:", "too few columns: 3 field(s) of 10 characters, the row needs 5");
  }
  // An unsupported data format.
  expectRefused(replace("#:LRFI", "#:KRFI"), "road.crg:", "data format 'KRFI' is not supported");
  // A missing value where none may be: in the banking channel.
  {
    CrgSpec spec = good;
    spec.extra_channels = {"reference line banking,m/m"};
    spec.extra = [](int k) { return std::vector<double>{k == 4 ? std::nan("") : 0.01}; };
    expectRefused(crgText(spec), "road.crg:", "banking channel: data row 5 is missing (NaN)");
  }
  // Options and sections the twin does not evaluate.
  expectRefused(replace("$ROAD_CRG\n", "$ROAD_CRG_OPTS\nBORDER_MODE_U = 3\n$\n$ROAD_CRG\n"),
                "road.crg:5: ", "BORDER_MODE_U = 3 is not supported");
  expectRefused(replace("$ROAD_CRG\n", "$ROAD_CRG_MODS\nSCALE_Z_GRID = 2\n$\n$ROAD_CRG\n"),
                "road.crg:5: ", "$ROAD_CRG_MODS: modifiers");
  expectRefused(replace("$ROAD_CRG\n", "$ROAD_CRG\nREFERENCE_LINE_WIDTH = 3\n"),
                "road.crg:5: ", "$ROAD_CRG: unknown key 'REFERENCE_LINE_WIDTH'");
  expectRefused(replace("D:long section at v = -1", "D:long section at w = -1"),
                "road.crg:", "needs a whole number N >= 1");
  expectRefused(replace("D:long section at v = -0.5", "D:long section at v = -1.0"),
                "road.crg: ", "closer than 1e-6 m (or given twice)");
  expectRefused(replace("$$$$$$$$10", "$$$$$$$$10") + " 0.1\n", "road.crg:", "too few columns");
  expectRefused(replace("$CT\n", "$XY\n"), "road.crg:1: ", "unknown section '$XY'");
  // A missing file.
  try {
    readCrg("/nonexistent/road.crg");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "/nonexistent/road.crg: cannot be read (an OpenCRG road file)");
  }
}
