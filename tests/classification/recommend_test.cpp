// Cost-aware recommendation: the cheapest model within the threshold, the best when every
// cheaper model is decisively worse, a configurable threshold, tie-breaking, the sentence.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "classification/recommend.hpp"
#include "common/errors.hpp"

using namespace dtwin;
using namespace dtwin::classify;

TEST(Recommend, CheapestWithinThresholdIsChosen) {
  // 2 ln B vs M1: M2 2.0, M3 4.2, M4 12 (decisively worse even though cheapest).
  const std::vector<ModelCost> models = {
      {"M1", -100.0, 8.1}, {"M2", -101.0, 4.0}, {"M3", -102.1, 1.0}, {"M4", -106.0, 0.5}};
  const Recommendation r = recommendAssembly(models);
  EXPECT_EQ(r.best, "M1");
  EXPECT_EQ(r.best_index, 0);
  EXPECT_EQ(r.recommended, "M3");
  EXPECT_EQ(r.recommended_index, 2);
  EXPECT_EQ(r.candidates, (std::vector<std::string>{"M1", "M2", "M3"}));
  EXPECT_NEAR(r.two_ln_b[2], 2 * 2.1, 1e-12);
  EXPECT_NEAR(r.two_ln_b[3], 12.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.cost_ratio, 8.1);
  EXPECT_EQ(r.explanation,
            "M3 is recommended: it is 8.1x cheaper than M1 (the best by evidence) and its "
            "evidence is not decisively worse (2 ln B = 4.2 < 10).");
}

TEST(Recommend, BestIsChosenWhenEveryCheaperModelIsDecisivelyWorse) {
  // M2 is exactly at the threshold (2 ln B = 10): decisively worse. M3 is dearer than M1.
  const std::vector<ModelCost> models = {{"M2", -5.0, 1.0}, {"M1", 0.0, 5.0}, {"M3", -1.0, 9.0}};
  const Recommendation r = recommendAssembly(models);
  EXPECT_EQ(r.recommended, "M1");
  EXPECT_EQ(r.best, "M1");
  EXPECT_EQ(r.candidates, (std::vector<std::string>{"M1", "M3"}));
  EXPECT_EQ(r.explanation,
            "M1 is recommended: it has the strongest evidence and every cheaper assembly is "
            "decisively worse (2 ln B \u2265 10).");
}

TEST(Recommend, ThresholdIsConfigurable) {
  const std::vector<ModelCost> models = {{"M1", 0.0, 5.0}, {"M2", -5.0, 1.0}};
  RecommendOptions o;
  o.threshold = 10.5;
  const Recommendation loose = recommendAssembly(models, o);
  EXPECT_EQ(loose.recommended, "M2");
  EXPECT_EQ(loose.explanation,
            "M2 is recommended: it is 5.0x cheaper than M1 (the best by evidence) and its "
            "evidence is not decisively worse (2 ln B = 10.0 < 10.5).");
  o.threshold = 2.0;
  const Recommendation strict = recommendAssembly(models, o);
  EXPECT_EQ(strict.recommended, "M1");
  EXPECT_NE(strict.explanation.find("(2 ln B \u2265 2)"), std::string::npos) << strict.explanation;
}

TEST(Recommend, TiesAndPrecisionOfTheSentence) {
  // Equal cost: the higher evidence wins; equal cost and evidence: the lower index.
  const Recommendation r1 =
      recommendAssembly({{"A", 0.0, 3.0}, {"B", -1.0, 1.0}, {"C", -0.5, 1.0}});
  EXPECT_EQ(r1.recommended, "C");
  const Recommendation r2 =
      recommendAssembly({{"A", 0.0, 3.0}, {"B", -1.0, 1.0}, {"C", -1.0, 1.0}});
  EXPECT_EQ(r2.recommended, "B");
  // The best is also the cheapest.
  const Recommendation r3 = recommendAssembly({{"A", 0.0, 1.0}, {"B", -1.0, 2.0}});
  EXPECT_EQ(r3.explanation,
            "A is recommended: it has the strongest evidence and no other assembly is cheaper.");
  // 2 ln B = 9.996 must not print as "10.0 < 10"; a 1.03x ratio must not print as "1.0x".
  const Recommendation r4 = recommendAssembly({{"A", 0.0, 1.03}, {"B", -4.998, 1.0}});
  EXPECT_EQ(r4.recommended, "B");
  EXPECT_NE(r4.explanation.find("1.03x cheaper than A"), std::string::npos) << r4.explanation;
  EXPECT_NE(r4.explanation.find("(2 ln B = 9.996 < 10)"), std::string::npos) << r4.explanation;
  // −∞ evidence is never a candidate.
  const Recommendation r5 =
      recommendAssembly({{"A", -3.0, 2.0}, {"B", -std::numeric_limits<double>::infinity(), 0.1}});
  EXPECT_EQ(r5.recommended, "A");
  EXPECT_EQ(r5.candidates, (std::vector<std::string>{"A"}));
}

TEST(Recommend, InvalidInputIsRejectedWithMessage) {
  auto message = [](const std::vector<ModelCost>& m, RecommendOptions o = {}) -> std::string {
    try {
      recommendAssembly(m, o);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message({}), "recommendation: no models given");
  EXPECT_EQ(message({{"M1", 0.0, 1.0}, {"M1", -1.0, 2.0}}),
            "recommendation: model 1 (M1): duplicate id");
  EXPECT_EQ(message({{"M1", 0.0, 0.0}}),
            "recommendation: model 0 (M1): cost must be > 0 and finite, got 0");
  EXPECT_EQ(message({{"M1", std::nan(""), 1.0}}),
            "recommendation: model 0 (M1): log_evidence must be finite or -inf, got nan");
  RecommendOptions o;
  o.threshold = -1.0;
  EXPECT_EQ(message({{"M1", 0.0, 1.0}}, o),
            "recommend.threshold: must be a finite number > 0, got -1");
}
