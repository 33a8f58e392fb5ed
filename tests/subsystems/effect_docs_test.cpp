// The effect tables of the docs against the registry (subsystems/effect.hpp effectRegistry):
// docs/model.md lists every effect with its kind and every parameter with its unit, off value,
// prior range and shape flag; docs/diagnosis.md lists every effect's residual signature and
// engagement threshold. A registered effect missing from a table, a row naming no registered
// effect or parameter, or a value that differs fails here (docs/extending.md).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "subsystems/effect.hpp"

namespace dtwin {
namespace {

std::string readDoc(const std::string& name) {
  const std::filesystem::path p = std::filesystem::path(DTWIN_SOURCE_DIR) / "docs" / name;
  std::ifstream in(p);
  EXPECT_TRUE(in) << "cannot read " << p;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t`");
  const auto b = s.find_last_not_of(" \t`");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// The cells of a Markdown table row "| a | b |" (trimmed, backticks removed).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::size_t a = line.find('|');
  while (a != std::string::npos) {
    const std::size_t b = line.find('|', a + 1);
    if (b == std::string::npos) break;
    out.push_back(trim(line.substr(a + 1, b - a - 1)));
    a = b;
  }
  return out;
}

/// The body rows of the table whose header row starts with `header`, keyed by their first cell.
std::map<std::string, std::vector<std::string>> table(const std::string& doc,
                                                      const std::string& header) {
  std::map<std::string, std::vector<std::string>> rows;
  const auto at = doc.find("\n" + header);
  EXPECT_NE(at, std::string::npos) << "no table with header " << header;
  if (at == std::string::npos) return rows;
  std::size_t pos = doc.find('\n', at + 1);  // end of the header row
  pos = doc.find('\n', pos + 1);             // end of the |---| row
  while (pos != std::string::npos && pos + 1 < doc.size() && doc[pos + 1] == '|') {
    const std::size_t end = doc.find('\n', pos + 1);
    const auto c = cells(doc.substr(pos + 1, end - pos - 1));
    if (!c.empty()) {
      EXPECT_EQ(rows.count(c[0]), 0u) << "row " << c[0] << " twice";
      rows[c[0]] = c;
    }
    pos = end;
  }
  return rows;
}

/// "[lo, hi]" -> {lo, hi}.
std::pair<double, double> range(const std::string& s) {
  const auto comma = s.find(',');
  if (s.size() < 5 || s.front() != '[' || s.back() != ']' || comma == std::string::npos) {
    ADD_FAILURE() << "not a range [lo, hi]: " << s;
    return {NAN, NAN};
  }
  return {std::stod(s.substr(1, comma - 1)), std::stod(s.substr(comma + 1, s.size() - comma - 2))};
}

bool same(double doc, double registry) {
  return doc == registry || std::abs(doc - registry) <= 1e-12 * std::abs(registry);
}

}  // namespace

TEST(EffectDocs, ModelMdListsEveryEffectAndParameterAsTheRegistrySays) {
  const std::string doc = readDoc("model.md");
  auto effects = table(doc, "| effect | kind | law |");
  auto params = table(doc, "| parameter | unit | off | prior range | shape |");
  for (const auto& entry : effectRegistry()) {
    SCOPED_TRACE("effect " + entry.name);
    const auto e = entry.value();
    const auto it = effects.find(entry.name);
    if (it == effects.end()) {
      ADD_FAILURE() << "docs/model.md: no row for effect " << entry.name;
    } else {
      ASSERT_GE(it->second.size(), 3u);
      EXPECT_EQ(it->second[1], kindName(e->kind()));
      EXPECT_FALSE(it->second[2].empty()) << "its law";
      effects.erase(it);
    }
    for (const auto& p : e->parameters()) {
      const std::string name = entry.name + "." + p.name;
      const auto row = params.find(name);
      if (row == params.end()) {
        ADD_FAILURE() << "docs/model.md: no row for parameter " << name;
        continue;
      }
      const auto& c = row->second;
      ASSERT_GE(c.size(), 5u) << name;
      EXPECT_EQ(c[1], p.unit) << name;
      EXPECT_TRUE(same(std::stod(c[2]), p.default_value))
          << name << ": off " << c[2] << ", registry " << p.default_value;
      const auto [lo, hi] = range(c[3]);
      EXPECT_TRUE(same(lo, p.prior_lower) && same(hi, p.prior_upper))
          << name << ": prior " << c[3] << ", registry [" << p.prior_lower << ", " << p.prior_upper
          << "]";
      EXPECT_EQ(c[4], p.shape ? "shape" : "") << name;
      params.erase(row);
    }
  }
  for (const auto& [name, row] : effects)
    ADD_FAILURE() << "docs/model.md: effect " << name << " is not registered";
  for (const auto& [name, row] : params)
    ADD_FAILURE() << "docs/model.md: parameter " << name << " is not registered";
}

TEST(EffectDocs, DiagnosisMdListsEverySignatureAsTheRegistrySays) {
  auto rows =
      table(readDoc("diagnosis.md"), "| effect | state map | feature | engagement threshold |");
  for (const auto& entry : effectRegistry()) {
    SCOPED_TRACE("effect " + entry.name);
    const auto e = entry.value();
    const auto it = rows.find(entry.name);
    if (it == rows.end()) {
      ADD_FAILURE() << "docs/diagnosis.md: no row for effect " << entry.name;
      continue;
    }
    ASSERT_GE(it->second.size(), 4u);
    const auto dash = [](const std::string& s) { return s.empty() ? std::string("–") : s; };
    EXPECT_EQ(it->second[1], dash(e->residualSignature().state_map));
    EXPECT_EQ(it->second[2], dash(e->residualSignature().feature));
    EXPECT_EQ(it->second[3], dash(e->engagementThreshold()));
    rows.erase(it);
  }
  for (const auto& [name, row] : rows)
    ADD_FAILURE() << "docs/diagnosis.md: effect " << name << " is not registered";
}

}  // namespace dtwin
