#include "pellicle/core/ordered_sum.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <random>
#include <vector>

namespace pellicle {
namespace {

//! Terms spread over many orders of magnitude and both signs, so that the order of the
//! additions shows in the last bits.
std::vector<double> wide_terms(long n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> exponent(-8.0, 8.0), sign(-1.0, 1.0);
  std::vector<double> x(n);
  for (double& v : x) v = std::copysign(std::pow(10.0, exponent(rng)), sign(rng));
  return x;
}

//! The same static shares the sum uses, summed one after another in thread order.
double shares_in_thread_order(const std::vector<double>& x, int threads) {
  const long n = static_cast<long>(x.size());
  std::vector<int> owner(n);
#pragma omp parallel num_threads(threads)
#pragma omp for schedule(static)
  for (long i = 0; i < n; ++i) owner[i] = omp_get_thread_num();
  double total = 0.0;
  for (int t = 0; t < threads; ++t) {
    double share = 0.0;
    for (long i = 0; i < n; ++i)
      if (owner[i] == t) share += x[i];
    total += share;
  }
  return total;
}

TEST(OrderedSum, AddsTheThreadsSharesInThreadOrder) {
  const std::vector<double> x = wide_terms(10007);
  const int before = omp_get_max_threads();
  for (int threads : {1, 2, 3, 5}) {
    omp_set_num_threads(threads);
    const double expected = shares_in_thread_order(x, threads);
    for (int repeat = 0; repeat < 20; ++repeat) {
      const double sum = ordered_sum(0, static_cast<long>(x.size()), [&](long i) { return x[i]; });
      ASSERT_EQ(sum, expected) << threads << " threads, repeat " << repeat;
    }
  }
  omp_set_num_threads(before);
}

TEST(OrderedSum, SeveralSumsAtOnce) {
  const std::vector<double> x = wide_terms(999);
  const int before = omp_get_max_threads();
  omp_set_num_threads(3);
  const auto sums =
      ordered_sums<2>(0, static_cast<long>(x.size()), [&](long i, std::array<double, 2>& s) {
        s[0] += x[i];
        s[1] += 1.0;
      });
  EXPECT_EQ(sums[0], shares_in_thread_order(x, 3));
  EXPECT_EQ(sums[1], 999.0);
  EXPECT_EQ(ordered_sum(5, 5, [&](long i) { return x[i]; }), 0.0);  // empty range
  omp_set_num_threads(before);
}

}  // namespace
}  // namespace pellicle
