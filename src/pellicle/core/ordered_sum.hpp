#pragma once
//! Parallel sums over an index range that come out the same in every run with the same number
//! of threads: each thread sums its static share in index order, and the shares are added in
//! thread order. An OpenMP reduction adds the shares in the order the threads finish, so with
//! three threads or more its last bits change from run to run; with one or two threads the
//! two give the same bits.

#include <omp.h>

#include <array>
#include <vector>

namespace pellicle {

//! N sums at once: add(i, sums) adds index i's terms to sums[0..N−1]. Call outside a parallel
//! region.
template <int N, class F>
std::array<double, N> ordered_sums(long begin, long end, F&& add) {
  std::vector<std::array<double, N>> shares(omp_get_max_threads(), std::array<double, N>{});
#pragma omp parallel
  {
    std::array<double, N> share{};
#pragma omp for schedule(static) nowait
    for (long i = begin; i < end; ++i) add(i, share);
    shares[omp_get_thread_num()] = share;
  }
  std::array<double, N> total{};
  for (const auto& share : shares)
    for (int k = 0; k < N; ++k) total[k] += share[k];
  return total;
}

//! Σ term(i) over [begin, end).
template <class F>
double ordered_sum(long begin, long end, F&& term) {
  return ordered_sums<1>(begin, end, [&](long i, std::array<double, 1>& s) { s[0] += term(i); })[0];
}

}  // namespace pellicle
