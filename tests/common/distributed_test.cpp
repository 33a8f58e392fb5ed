// distributedMap and its helpers in one process (the MPI runs are in mpi_cli_test.cpp): results
// in index order for any thread count, the lowest failing index's error with its type, packing,
// exceptions carried as bytes, onRoot.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

#include "common/distributed.hpp"
#include "common/errors.hpp"
#include "common/run_error.hpp"

using namespace dtwin;

TEST(Distributed, SingleProcessWithoutLauncher) {
  const Distributed d;  // not started by a launcher: one process
  EXPECT_EQ(processRank(nullptr), 0);
  EXPECT_EQ(processCount(nullptr), 1);
  EXPECT_TRUE(isRootProcess(nullptr));
  EXPECT_EQ(threadsPerProcess(nullptr, 3), 3);
  EXPECT_EQ(processCount(&d), 1);
  EXPECT_EQ(threadsPerProcess(&d, 0), 0);
  EXPECT_EQ(d.rank(), 0);
  EXPECT_EQ(d.size(), 1);
  EXPECT_TRUE(d.isRoot());
  EXPECT_EQ(d.threadsPerRank(3), 3);
  EXPECT_EQ(d.threadsPerRank(0), 0);  // one process: workerCount decides (all cores)
}

TEST(Distributed, MapReturnsEveryResultInIndexOrderForAnyThreadCount) {
  const Distributed one;
  for (const Distributed* processes : {static_cast<const Distributed*>(nullptr), &one})
    for (int threads : {1, 2, 4}) {
      std::atomic<int> calls{0};
      std::vector<std::size_t> last;
      const auto r = distributedMap(
          processes, 37, threads,
          [&](std::size_t i, int w) {
            EXPECT_LT(w, distributedWorkers(processes, 37, threads));
            ++calls;
            return std::vector<double>(i % 4, static_cast<double>(i) + 0.5);
          },
          [&](std::size_t done, std::size_t total) {
            EXPECT_EQ(total, 37u);
            last.push_back(done);
          });
      EXPECT_EQ(calls.load(), 37);
      ASSERT_EQ(r.size(), 37u);
      for (std::size_t i = 0; i < r.size(); ++i) {
        ASSERT_EQ(r[i].size(), i % 4) << i;
        for (double v : r[i]) EXPECT_EQ(v, static_cast<double>(i) + 0.5);
      }
      ASSERT_FALSE(last.empty());
      EXPECT_EQ(last.back(), 37u);
    }
  EXPECT_TRUE(distributedMap(nullptr, 0, 2, [](std::size_t, int) {
                return std::vector<double>{1.0};
              }).empty());
}

TEST(Distributed, MapRethrowsTheLowestFailingIndexWithItsType) {
  for (int threads : {1, 3}) {
    try {
      distributedMap(nullptr, 50, threads, [](std::size_t i, int) -> std::vector<double> {
        if (i == 7 || i == 30) throw InputError("task " + std::to_string(i), "fails");
        return {1.0};
      });
      FAIL() << "no exception";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), "task 7");
    }
    EXPECT_THROW(distributedMap(nullptr, 5, threads,
                                [](std::size_t i, int) -> std::vector<double> {
                                  if (i == 2) throw RunFailedError("run 3 failed", 3, 42);
                                  return {};
                                }),
                 RunFailedError);
  }
}

TEST(Distributed, PackerRoundTrip) {
  const std::vector<double> v =
      Packer()
          .put(3.25)
          .put(std::vector<double>{1, 2, std::numeric_limits<double>::infinity()})
          .put(std::string("status \xC3\xA9\n,\0x", 11))
          .put(static_cast<double>((1ULL << 53) - 1))
          .put(std::vector<double>{})
          .take();
  Unpacker u(v);
  EXPECT_EQ(u.num(), 3.25);
  const auto a = u.vec();
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[2], std::numeric_limits<double>::infinity());
  EXPECT_EQ(u.str(), std::string("status \xC3\xA9\n,\0x", 11));
  EXPECT_EQ(static_cast<unsigned long long>(u.integer()), (1ULL << 53) - 1);
  EXPECT_TRUE(u.vec().empty());
  EXPECT_THROW(u.num(), std::logic_error);
  const std::vector<double> d{1.5, -0.0, 1e-300};
  EXPECT_EQ(bytesToDoubles(doublesToBytes(d)), d);
}

TEST(Distributed, ExceptionsTravelAsBytes) {
  auto roundTrip = [](auto ex) {
    try {
      throwEncoded(encodeException(std::make_exception_ptr(ex)));
    } catch (...) {
      return std::current_exception();
    }
    return std::exception_ptr();
  };
  try {
    std::rethrow_exception(roundTrip(InputError("file.toml: a.b", "must be > 0, got -1")));
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "file.toml: a.b");
    EXPECT_EQ(e.rule(), "must be > 0, got -1");
  }
  try {
    std::rethrow_exception(roundTrip(RunFailedError("field run 4 failed", 4, 123456789012345ULL)));
  } catch (const RunFailedError& e) {
    EXPECT_STREQ(e.what(), "field run 4 failed");
    EXPECT_EQ(e.run(), 4u);
    EXPECT_EQ(e.seed(), 123456789012345ULL);
  }
  EXPECT_THROW(std::rethrow_exception(roundTrip(std::logic_error("x"))), std::logic_error);
  try {
    std::rethrow_exception(roundTrip(std::out_of_range("range: 12")));
  } catch (const std::logic_error& e) {  // out_of_range is a logic_error: kept as one
    EXPECT_STREQ(e.what(), "range: 12");
  }
  try {
    std::rethrow_exception(roundTrip(std::runtime_error("disk full")));
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "disk full");
  }
}

TEST(Distributed, OnRootRunsHereAndPassesErrorsOn) {
  const Distributed one;
  for (const Distributed* processes : {static_cast<const Distributed*>(nullptr), &one}) {
    EXPECT_EQ(onRoot(processes, [] { return std::string("abc"); }), "abc");
    EXPECT_THROW(onRoot(processes, []() -> std::string { throw InputError("x", "y"); }),
                 InputError);
  }
  one.barrier();  // a no-op with one process
}
