// One-line messages: printable() escapes the control bytes of quoted user text, InputError applies
// it to both parts, oneLine() folds another library's multi-line message, a JSON library's
// error identifiers are dropped (jsonErrorInWords), and an internal error's prefix is shown once.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "common/format.hpp"
#include "common/json.hpp"

namespace {

TEST(Messages, PrintableEscapesEveryControlByteAndKeepsUtf8) {
  EXPECT_EQ(dtwin::printable("a\rb\nc\td"), "a\\rb\\nc\\td");
  EXPECT_EQ(dtwin::printable(std::string("x\0y", 3)), "x\\x00y");
  EXPECT_EQ(dtwin::printable("\x1b[31m\x7f"), "\\x1b[31m\\x7f");
  EXPECT_EQ(dtwin::printable("Grüße, 95 %"), "Grüße, 95 %");
}

TEST(Messages, InputErrorIsOneLineWhateverItQuotes) {
  const dtwin::InputError e("lab.csv:1", "header: unexpected column 'time\r\n_s'");
  const std::string what = e.what();
  EXPECT_EQ(what.find('\n'), std::string::npos);
  EXPECT_EQ(what.find('\r'), std::string::npos);
  EXPECT_EQ(what, "lab.csv:1: header: unexpected column 'time\\r\\n_s'");
  EXPECT_EQ(e.rule(), "header: unexpected column 'time\\r\\n_s'");
}

// An internal error is shown with its prefix once: DTWIN_CHECK's message carries it already.
TEST(Messages, AnInternalErrorCarriesItsPrefixOnce) {
  try {
    DTWIN_CHECK(1 + 1 == 3, "arithmetic");
    FAIL() << "DTWIN_CHECK did not throw";
  } catch (const std::logic_error& e) {
    const std::string text = dtwin::internalErrorText(e.what());
    EXPECT_EQ(text.rfind("internal error: arithmetic [1 + 1 == 3] (", 0), 0u) << text;
    EXPECT_EQ(text.find("internal error: internal error"), std::string::npos) << text;
  }
  EXPECT_EQ(dtwin::internalErrorText("[json.exception.type_error.302] type must be number"),
            "internal error: [json.exception.type_error.302] type must be number");
}

TEST(Messages, OneLineFoldsWhiteSpaceRuns) {
  EXPECT_EQ(dtwin::oneLine("SimTK Exception thrown at X.h:524:\n  Error detected\n  (Required.)\n"),
            "SimTK Exception thrown at X.h:524: Error detected (Required.)");
  EXPECT_EQ(dtwin::oneLine("  \n\t "), "");
  EXPECT_EQ(dtwin::oneLine("one line"), "one line");
}

TEST(Messages, ALibrarysIdentifiersDoNotReachTheUser) {
  // nlohmann's bracketed exception id is dropped; the position and the reason stay.
  try {
    const auto parsed = nlohmann::json::parse("{\"a\": ");
    (void)parsed;
    FAIL() << "parsed";
  } catch (const nlohmann::json::exception& e) {
    const std::string w = dtwin::jsonErrorInWords(e);
    EXPECT_EQ(w.find("json.exception"), std::string::npos) << w;
    EXPECT_NE(w.find("parse error"), std::string::npos) << w;
  }
  EXPECT_EQ(dtwin::jsonErrorInWords(std::runtime_error("plain")), "plain");
}

}  // namespace
