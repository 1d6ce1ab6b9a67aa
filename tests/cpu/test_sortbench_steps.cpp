// sortbench --steps' bookkeeping (app/sortbench_steps.h): each step's median over the runs, its share of the
// sort's median, in the order the sort records the steps; runs that do not match are refused, not mixed.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/sortbench_steps.h"

namespace raylab {
namespace {

std::vector<StageTime> run(double sort, double histogram, double scatter) {
  return {{"sort", -1, sort}, {"histogram/0", -1, histogram}, {"scatter/0", -1, scatter}};
}

TEST(SortSteps, MediansAndSharesInTheSortsOrder) {
  SortSteps steps;
  EXPECT_TRUE(steps.empty());
  steps.addRun(run(10.0, 3.0, 5.0), "sort");
  steps.addRun(run(12.0, 1.0, 9.0), "sort");
  steps.addRun(run(11.0, 2.0, 7.0), "sort");
  EXPECT_FALSE(steps.empty());
  // Medians 2 and 7 (min 1 and 5, max 3 and 9); shares of a sort median of 10.
  EXPECT_EQ(steps.csv("radix", 1000, 10.0, ",x"),
            "radix,1000,histogram/0,2.000000,1.000000,3.000000,0.2000,x\n"
            "radix,1000,scatter/0,7.000000,5.000000,9.000000,0.7000,x\n");
  const std::string table = steps.table(10.0);
  EXPECT_LT(table.find("histogram/0"), table.find("scatter/0"));
  EXPECT_NE(table.find("70.0%"), std::string::npos) << table;
}

TEST(SortSteps, AnEvenCountTakesTheMiddlePairsMean) {
  SortSteps steps;
  steps.addRun(run(4.0, 1.0, 2.0), "sort");
  steps.addRun(run(4.0, 2.0, 2.0), "sort");
  EXPECT_EQ(steps.csv("radix", 8, 4.0, ""), "radix,8,histogram/0,1.500000,1.000000,2.000000,0.3750\n"
                                            "radix,8,scatter/0,2.000000,2.000000,2.000000,0.5000\n");
}

TEST(SortSteps, RunsThatDoNotMatchAreRefused) {
  SortSteps steps;
  EXPECT_THROW(steps.addRun({{"histogram/0", -1, 1.0}}, "sort"), std::logic_error);  // no sort scope first
  EXPECT_THROW(steps.addRun({}, "sort"), std::logic_error);
  steps.addRun(run(10.0, 3.0, 5.0), "sort");
  const std::string before = steps.csv("radix", 1, 10.0, "");
  EXPECT_THROW(steps.addRun({{"sort", -1, 1.0}, {"histogram/0", -1, 1.0}}, "sort"), std::logic_error);  // fewer
  EXPECT_THROW(steps.addRun({{"sort", -1, 1.0}, {"histogram/0", -1, 1.0}, {"scan/0", -1, 1.0}}, "sort"),
               std::logic_error);  // another step in the same place
  EXPECT_EQ(steps.csv("radix", 1, 10.0, ""), before) << "a refused run left times behind";
}

}  // namespace
}  // namespace raylab
