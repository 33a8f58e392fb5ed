// docs/registries.md is `twin list --registries`, byte for byte: every registry of the twin (tire
// and strut laws, suspension options, effects, road types, sensor quantities and models,
// integrators, commands, the variables of user-defined effects) with its names, descriptions and
// parameters. A registry entry added, removed or changed without regenerating the page fails
// here, and so does an edit of the page that the registries do not hold.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <sstream>
#include <string>

#include "test_util.hpp"

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

TEST(RegistryDocs, RegistriesMdIsWhatTheRegistriesHold) {
  const auto dir = dtwin_test::freshDir("registry_docs");
  const std::string out = (dir / "registries.md").string();
  const int st = std::system((std::string(DTWIN_TWIN_EXE) + " list --registries > " + out).c_str());
  ASSERT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
  const auto generated = lines(dtwin_test::slurp(out));
  const auto doc = lines(dtwin_test::slurp(std::string(DTWIN_SOURCE_DIR) + "/docs/registries.md"));
  ASSERT_GT(generated.size(), 50u);
  for (const char* must :
       {"## Tire laws", "## Strut laws", "## Suspension options", "## Effects", "## Road types",
        "## Sensor quantities", "## Sensor models", "## Integrators", "## Commands",
        "## Variables of user-defined effects"}) {
    bool found = false;
    for (const auto& l : generated) found = found || l.rfind(must, 0) == 0;
    EXPECT_TRUE(found) << "twin list --registries has no section " << must;
  }
  // Line by line, so that a failure names the first row that differs.
  for (std::size_t i = 0; i < std::max(generated.size(), doc.size()); ++i) {
    const std::string g = i < generated.size() ? generated[i] : "(end)",
                      d = i < doc.size() ? doc[i] : "(end)";
    ASSERT_EQ(d, g) << "docs/registries.md line " << i + 1
                    << " differs from `twin list --registries`; regenerate: ./build/cli/twin list "
                       "--registries > docs/registries.md";
  }
}
