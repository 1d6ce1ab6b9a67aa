// `--shard i/K`: parsed strictly (0 <= i < K), and the K shards of a plan are disjoint and together cover it,
// cell n in shard n mod K.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/bench/bench_shard.h"

namespace raylab {
namespace {

TEST(BenchShard, ShardsAreDisjointAndCoverThePlan) {
  for (uint32_t k : {1u, 2u, 3u, 7u}) {
    std::vector<int> owners(100, 0);
    for (uint32_t i = 0; i < k; ++i) {
      const BenchShard s = parseShard(std::to_string(i) + "/" + std::to_string(k));
      EXPECT_EQ(s.index, i);
      EXPECT_EQ(s.count, k);
      for (size_t n = 0; n < owners.size(); ++n)
        if (s.contains(n)) {
          ++owners[n];
          EXPECT_EQ(n % k, i);
        }
    }
    for (size_t n = 0; n < owners.size(); ++n) EXPECT_EQ(owners[n], 1) << "cell " << n << " with K=" << k;
  }
  EXPECT_TRUE(BenchShard{}.whole());
  EXPECT_EQ(parseShard("2/5").text(), "2/5");
}

TEST(BenchShard, BadShardsAreRefused) {
  for (const char* bad : {"3/3", "1/0", "0", "/2", "1/", "-1/2", "a/b", "1/2/3", "0/5000", " 0/2"}) {
    try {
      parseShard(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--shard expects i/K"), std::string::npos) << e.what();
    }
  }
}

TEST(BenchShard, TakenOutOfTheArguments) {
  std::vector<std::string> args{"--cases", "cornell@front", "--shard", "1/4", "--size", "8x8"};
  EXPECT_EQ(takeShard(args), (BenchShard{1, 4}));
  EXPECT_EQ(args, (std::vector<std::string>{"--cases", "cornell@front", "--size", "8x8"}));
  std::vector<std::string> none{"--size", "8x8"};
  EXPECT_TRUE(takeShard(none).whole());
  std::vector<std::string> dangling{"--shard"};
  EXPECT_THROW(takeShard(dangling), UsageError);
}

}  // namespace
}  // namespace raylab
