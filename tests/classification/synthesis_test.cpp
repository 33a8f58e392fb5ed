// Synthetic field data of a calibrated assembly (classification/synthesis.hpp) on the real twin,
// at tiny sizes: M3 (the cheapest assembly), a 0.5 s window (p = 501), a handful of draws.
#include <gtest/gtest.h>

#include "shipped_study.hpp"
#include "test_util.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "classification/synthesis.hpp"
#include "common/checksum.hpp"
#include "common/errors.hpp"
#include "study/generate.hpp"

namespace fs = std::filesystem;
using namespace dtwin;
using namespace dtwin::classify;
using dtwin::calib::readPosteriorCsv;

namespace {

const Study& demo() { return dtwin_test::shippedStudy("demo"); }

using dtwin_test::slurp;

fs::path tempDir(const std::string& name) {
  return dtwin_test::freshDir("dtwin_synthesis_" + name);
}
using dtwin_test::writeText;

// A small posterior around the demo study's truth (tau ~ 1/18000 N^-2).
const char* kPosterior =
    "tire.stiffness,tire.damping,suspension.stiffness,suspension.damping,tau,design_index\n"
    "180000,3000,30000,2500,5.5e-05,0\n"
    "181000,2950,30500,2450,5.6e-05,1\n"
    "179000,3050,29500,2550,5.4e-05,2\n";

SynthesisOptions tiny(int threads) {
  SynthesisOptions o;
  o.draws = 6;
  o.roads_per_draw = 2;
  o.road_library = 20;
  o.block = 2;
  o.leaf_blocks = 1;  // three leaves: a tree with a merge and a promoted node
  o.threads = threads;
  o.seed = 99;
  o.t_begin_s = 10.0;
  o.t_end_s = 10.5;
  return o;
}

PosteriorSample posterior(const fs::path& dir, const std::string& text = kPosterior) {
  writeText(dir / "posterior.csv", text);
  return readPosteriorCsv((dir / "posterior.csv").string());
}

}  // namespace

TEST(Synthesis, LibrarySeedsAreA53BitStreamOfTheirOwn) {
  EXPECT_EQ(librarySeed(1, 0), librarySeed(1, 0));
  EXPECT_NE(librarySeed(1, 0), librarySeed(1, 1));
  EXPECT_NE(librarySeed(1, 0), fieldRoadSeed(1, 1));  // not the field data's roads
  for (std::uint64_t i = 0; i < 100; ++i) EXPECT_LT(librarySeed(7, i), 1ULL << 53);
}

TEST(Synthesis, PosteriorMustNameTheStudysCalibratedParameters) {
  const fs::path dir = tempDir("names");
  const auto ps = posterior(
      dir,
      "tire.damping,tire.stiffness,suspension.stiffness,suspension.damping,tau,design_index\n"
      "3000,180000,30000,2500,5.5e-05,0\n");
  try {
    synthesizeAssembly(demo(), demo().assembly("M3"), ps, tiny(1), (dir / "out").string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("are not the study's calibrated parameters"),
              std::string::npos)
        << e.what();
  }
}

// 1 and 2 threads: bit-identical moments.bin (fixed blocks, ordered reduction).
TEST(Synthesis, ThreadCountDoesNotChangeTheMoments) {
  const fs::path dir = tempDir("threads");
  const auto ps = posterior(dir);
  const auto a = demo().assembly("M3");
  const auto r1 = synthesizeAssembly(demo(), a, ps, tiny(1), (dir / "t1").string());
  const auto r2 = synthesizeAssembly(demo(), a, ps, tiny(2), (dir / "t2").string());
  EXPECT_EQ(r1.moments.count(), 12);
  EXPECT_EQ(r1.moments.dimension(), 501);
  EXPECT_EQ(r1.failures, 0);
  EXPECT_GT(r1.cost_s_per_s, 0.0);
  EXPECT_EQ(r1.fingerprint, r2.fingerprint);
  const std::string b1 = slurp(dir / "t1" / "moments.bin"), b2 = slurp(dir / "t2" / "moments.bin");
  ASSERT_FALSE(b1.empty());
  EXPECT_TRUE(b1 == b2) << "moments.bin differs between 1 and 2 threads";
  // The mean is a hub force near the static load (a few kN), the variance at least the noise's.
  EXPECT_GT(r1.moments.mean()[0], 1000.0);
  EXPECT_GT(r1.moments.covariance()(0, 0), 1.0 / 5.6e-5 * 0.3);
  EXPECT_FALSE(fs::exists(dir / "t1" / "checkpoint.json"));
  const auto j = nlohmann::json::parse(slurp(dir / "t1" / "synthesis.json"));
  EXPECT_EQ(j["vectors"], 12);
  EXPECT_EQ(j["samples"], 501);
  EXPECT_EQ(j["fingerprint"], r1.fingerprint);
  EXPECT_TRUE(j["branched"].get<bool>());
}

// Interrupted (an exception from the progress callback after a few draws) and rerun: the same
// moments.bin as an uninterrupted run; a third run reuses the files; other sizes are refused.
TEST(Synthesis, ResumesAfterAnInterruptionBitIdentically) {
  const fs::path dir = tempDir("resume");
  const auto ps = posterior(dir);
  const auto a = demo().assembly("M3");
  SynthesisOptions o = tiny(2);
  o.checkpoint_interval_s = 0.0;  // checkpoint after every block
  synthesizeAssembly(demo(), a, ps, o, (dir / "full").string());
  const std::string out = (dir / "cut").string();
  EXPECT_THROW(synthesizeAssembly(demo(), a, ps, o, out,
                                  [](std::size_t done, std::size_t) {
                                    if (done >= 3) throw std::runtime_error("interrupted");
                                  }),
               std::runtime_error);
  ASSERT_TRUE(fs::exists(dir / "cut" / "checkpoint.json"));
  EXPECT_FALSE(fs::exists(dir / "cut" / "moments.bin"));
  {  // the checkpoint names the tree's nodes so far, each in its own file
    const auto ck = nlohmann::json::parse(slurp(dir / "cut" / "checkpoint.json"));
    ASSERT_FALSE(ck["nodes"].empty());
    for (const auto& n : ck["nodes"])
      EXPECT_TRUE(fs::exists(dir / "cut" / n["file"].get<std::string>())) << n.dump();
  }
  const auto r = synthesizeAssembly(demo(), a, ps, o, out);
  EXPECT_GE(r.resumed_blocks, 1);
  EXPECT_LT(r.resumed_blocks, 3);
  EXPECT_FALSE(r.reused);
  EXPECT_TRUE(slurp(dir / "full" / "moments.bin") == slurp(dir / "cut" / "moments.bin"))
      << "resumed moments differ";
  EXPECT_FALSE(fs::exists(dir / "cut" / "checkpoint.json"));
  for (const auto& e : fs::directory_iterator(dir / "cut"))
    EXPECT_EQ(e.path().filename().string().rfind("node_", 0), std::string::npos) << e.path();
  const auto again = synthesizeAssembly(demo(), a, ps, o, out);
  EXPECT_TRUE(again.reused);
  EXPECT_EQ(again.moments.count(), r.moments.count());
  SynthesisOptions other = o;
  other.draws = 8;
  EXPECT_THROW(synthesizeAssembly(demo(), a, ps, other, out), InputError);
}

// A checkpoint changed on disk (bytes of checkpoint.json overwritten, or a node file's): set aside
// with one note, the synthesis started again, and the same moments.bin as an undisturbed run.
TEST(Synthesis, ADamagedCheckpointIsSetAsideAndTheSynthesisRedone) {
  const fs::path dir = tempDir("damaged");
  const auto ps = posterior(dir);
  const auto a = demo().assembly("M3");
  SynthesisOptions o = tiny(2);
  o.checkpoint_interval_s = 0.0;  // checkpoint after every block
  synthesizeAssembly(demo(), a, ps, o, (dir / "full").string());
  const std::string full = slurp(dir / "full" / "moments.bin");
  for (const std::string damage : {"checkpoint", "node"}) {
    const fs::path cut = dir / ("cut_" + damage);
    EXPECT_THROW(synthesizeAssembly(demo(), a, ps, o, cut.string(),
                                    [](std::size_t done, std::size_t) {
                                      if (done >= 3) throw std::runtime_error("interrupted");
                                    }),
                 std::runtime_error);
    const fs::path ck = cut / "checkpoint.json";
    ASSERT_TRUE(fs::exists(ck));
    const auto j = nlohmann::json::parse(slurp(ck));
    ASSERT_TRUE(j.contains("checksum"));
    const fs::path node = cut / j["nodes"][0]["file"].get<std::string>();
    EXPECT_EQ(j["nodes"][0]["checksum"], contentChecksum(slurp(node)));  // of the node file's bytes
    const fs::path target = damage == "checkpoint" ? ck : node;
    std::string bytes = slurp(target);
    bytes[bytes.size() / 2] =
        static_cast<char>(bytes[bytes.size() / 2] ^ 0x10);  // one byte in the middle
    writeText(target, bytes);
    ::testing::internal::CaptureStderr();
    const auto r = synthesizeAssembly(demo(), a, ps, o, cut.string());
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(r.resumed_blocks, 0) << damage;  // nothing of it trusted
    EXPECT_TRUE(slurp(cut / "moments.bin") == full)
        << damage << ": moments differ from the undisturbed run's";
    EXPECT_TRUE(fs::exists(cut / "checkpoint.json.corrupt")) << damage;
    const std::string what = damage == "checkpoint" ? ""
                                                    : "its node file " + node.filename().string() +
                                                          " fails its checksum";
    EXPECT_EQ(err.rfind("twin: note: " + ck.string() + ": " + what, 0), 0u) << err;
    EXPECT_NE(err.find("the stage is redone, not trusted"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  }
}

// A draw whose parameters the model rejects: its runs are failures, counted and listed, and its
// vectors are left out; the result stays deterministic.
TEST(Synthesis, FailedRunsAreCountedAndSkipped) {
  const fs::path dir = tempDir("failures");
  const auto ps = posterior(
      dir,
      "tire.stiffness,tire.damping,suspension.stiffness,suspension.damping,tau,design_index\n"
      "180000,3000,30000,2500,5.5e-05,0\n"
      "-1,3000,30000,2500,5.5e-05,1\n");
  const auto a = demo().assembly("M3");
  const auto r1 = synthesizeAssembly(demo(), a, ps, tiny(2), (dir / "a").string());
  const auto r2 = synthesizeAssembly(demo(), a, ps, tiny(1), (dir / "b").string());
  EXPECT_GT(r1.failures, 0);
  EXPECT_LT(r1.failures, 12);
  EXPECT_EQ(r1.failures % 2, 0);  // a rejected θ fails both roads of its draw
  EXPECT_EQ(r1.moments.count() + r1.failures, 12);
  ASSERT_EQ(r1.failure_list.size(), static_cast<std::size_t>(r1.failures));
  EXPECT_NE(r1.failure_list[0].message.find("stiffness"), std::string::npos)
      << r1.failure_list[0].message;
  EXPECT_TRUE(slurp(dir / "a" / "moments.bin") == slurp(dir / "b" / "moments.bin"));
  const auto j = nlohmann::json::parse(slurp(dir / "a" / "synthesis.json"));
  EXPECT_EQ(j["failures"], r1.failures);
  EXPECT_EQ(j["failure_list"].size(), static_cast<std::size_t>(r1.failures));
}

// Options errors name the field as "synthesis.<field>" (common/validate.hpp), checked before any
// simulation; the sizes once resolved against the study.
TEST(Synthesis, OptionsNameTheField) {
  const fs::path dir = tempDir("options");
  const auto ps = posterior(dir);
  auto where = [&](const SynthesisOptions& o) -> std::string {
    try {
      synthesizeAssembly(demo(), demo().assembly("M3"), ps, o, (dir / "out").string());
    } catch (const InputError& e) {
      return e.where();
    }
    return "no error";
  };
  SynthesisOptions o = tiny(1);
  EXPECT_NO_THROW(o.validate());
  o.block = 0;
  EXPECT_EQ(where(o), "synthesis.block");
  o = tiny(1);
  o.t_begin_s = 11.0;  // after t_end_s
  EXPECT_EQ(where(o), "synthesis.t_begin_s");
  o = tiny(1);
  o.t_end_s = 99.0;  // outside the scenario
  EXPECT_EQ(where(o), "synthesis.t_end_s");
  o = tiny(1);
  o.checkpoint_interval_s = -1.0;
  EXPECT_EQ(where(o), "synthesis.checkpoint_interval_s");
  o = tiny(1);
  o.channel = "no_such_channel";
  EXPECT_EQ(where(o), "synthesis.channel");
  o = tiny(1);
  o.road_library = 1;  // fewer than the roads per draw
  EXPECT_EQ(where(o), "synthesis.road_library");
  EXPECT_FALSE(fs::exists(dir / "out"));
}
