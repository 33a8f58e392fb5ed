// common/csv.hpp: the CSV reader every log and data file goes through.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/csv.hpp"
#include "common/errors.hpp"

using dtwin::CsvReader;

namespace {

/// Every line's fields, joined by '|', lines by '/'.
std::string readAll(const std::string& text, char sep = ',') {
  CsvReader r(text, "f.csv", sep);
  std::string out;
  while (r.next()) {
    if (!out.empty()) out += "/";
    for (std::size_t i = 0; i < r.fields().size(); ++i)
      out += (i ? "|" : "") + std::string(r.fields()[i]);
  }
  return out;
}

}  // namespace

TEST(Csv, ByteOrderMarkCarriageReturnsBlankLinesSpacesAndQuotes) {
  EXPECT_EQ(readAll("\xEF\xBB\xBF"
                    "a, b ,c\r\n\r\n  \n1,,\"x, \"\"y\"\"\"\r\n"),
            "a|b|c/1||x, \"y\"");
  EXPECT_EQ(readAll("a;b\n1,5;2\n", ';'), "a|b/1,5|2");
  EXPECT_EQ(readAll("a\tb\t\tc\n", '\t'), "a|b||c") << "a tab separator keeps an empty cell";
}

TEST(Csv, WhitespaceTakesARunOfSpacesAndTabsAsOneSeparator) {
  EXPECT_EQ(readAll("   time    speed\tacc  \n  0.00   12.5 \t -0.01\n", ' '),
            "time|speed|acc/0.00|12.5|-0.01");
  EXPECT_EQ(readAll("\"a b\"  c\n", ' '), "a b|c");
  CsvReader r("\"a\"b c\n", "f.csv", ' ');
  try {
    r.next();
    FAIL();
  } catch (const dtwin::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.csv:1: text after a closing double quote"),
              std::string::npos)
        << e.what();
  }
}

TEST(Csv, LineNumbersCountBlankLinesAndAnOpenQuoteIsAnError) {
  CsvReader r("a\n\nb\n\"c\n", "f.csv");
  ASSERT_TRUE(r.next());
  EXPECT_EQ(r.line(), 1);
  ASSERT_TRUE(r.next());
  EXPECT_EQ(r.where(), "f.csv:3");
  try {
    r.next();
    FAIL();
  } catch (const dtwin::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("f.csv:4: a double quote is not closed"),
              std::string::npos)
        << e.what();
  }
}

TEST(Csv, NumbersAreWholeFields) {
  double v = 0;
  EXPECT_TRUE(dtwin::parseNumber("+1.5e3", v));
  EXPECT_EQ(v, 1500.0);
  EXPECT_TRUE(dtwin::parseNumber("-0.25", v));
  EXPECT_EQ(v, -0.25);
  for (const char* bad : {"", "+", "1.5x", "1,5", " 1", "0x10"})
    EXPECT_FALSE(dtwin::parseNumber(bad, v)) << bad;
}
