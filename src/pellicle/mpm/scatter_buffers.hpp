#pragma once
//! Race-free scatter to the grid with OpenMP. Each thread first reports the node range its
//! points touch. Thread 0 writes into the grid itself; every other thread writes into the grid
//! the nodes no other thread touches (its window) and the rest into a private copy of the node
//! fields, which is summed into the grid afterwards and left zeroed for the next scatter.
//! Points lie in the order they were placed, so the ranges of a static schedule overlap
//! only where two threads' points meet: most of a thread's nodes are in its window.
//! Every node receives the same terms in the same order as with private copies only.

#include <omp.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "pellicle/mpm/grid.hpp"

namespace pellicle {

template <int D>
struct NodeFields {
  double* mass;
  Vec<D>* momentum;
  Vec<D>* force;
};

//! Where a thread writes: the grid for nodes in [window_first, window_last], else `copy`.
template <int D>
struct ScatterTarget {
  NodeFields<D> grid, copy;
  long window_first, window_last;
  const NodeFields<D>& at(long node) const {
    return node >= window_first && node <= window_last ? grid : copy;
  }
};

template <int D>
class ScatterBuffers {
 public:
  //! Call before a parallel scatter, outside the parallel region.
  void prepare(const Grid<D>& grid) {
    const int threads = omp_get_max_threads();
    if (static_cast<int>(buffers_.size()) != threads - 1 ||
        (threads > 1 && static_cast<long>(buffers_[0].mass.size()) != grid.node_count())) {
      buffers_.assign(threads - 1, Buffer{});
      for (auto& b : buffers_) {
        b.mass.assign(grid.node_count(), 0.0);
        b.momentum.assign(grid.node_count(), Vec<D>::Zero());
        b.force.assign(grid.node_count(), Vec<D>::Zero());
      }
    }
    touched_.assign(threads, {std::numeric_limits<long>::max(), -1});
    windows_.assign(threads, {0, -1});
  }
  //! Record the node range [lo, hi] thread t will write to; every thread, then a barrier,
  //! then target().
  void touched(int t, long lo, long hi) { touched_[t] = {lo, hi}; }

  //! Where thread t writes (after every thread's touched() and a barrier).
  ScatterTarget<D> target(int t, Grid<D>& grid) {
    const NodeFields<D> direct{grid.mass.data(), grid.momentum.data(), grid.force.data()};
    if (t == 0)
      return {direct, direct, std::numeric_limits<long>::min(), std::numeric_limits<long>::max()};
    // The part of this thread's range no other thread's range reaches (empty when another
    // range lies strictly inside it).
    long first = touched_[t].first, last = touched_[t].second;
    for (int s = 0; s < static_cast<int>(touched_.size()) && first <= last; ++s) {
      const auto [lo, hi] = touched_[s];
      if (s == t || hi < first || lo > last) continue;
      if (lo <= first)
        first = hi + 1;
      else if (hi >= last)
        last = lo - 1;
      else
        last = first - 1;
    }
    windows_[t] = {first, last};
    Buffer& b = buffers_[t - 1];
    return {direct, {b.mass.data(), b.momentum.data(), b.force.data()}, first, last};
  }

  //! Sum the private copies into the grid and zero them again.
  void reduce(Grid<D>& grid, bool with_mass, bool with_momentum, bool with_force) {
    for (int t = 1; t < static_cast<int>(touched_.size()); ++t) {
      Buffer& b = buffers_[t - 1];
      const auto [lo, hi] = touched_[t];
      const auto [window_first, window_last] = windows_[t];
#pragma omp parallel for schedule(static)
      for (long n = lo; n <= hi; ++n) {
        if (n >= window_first && n <= window_last) continue;  // written to the grid directly
        if (with_mass) {
          grid.mass[n] += b.mass[n];
          b.mass[n] = 0.0;
        }
        if (with_momentum) {
          grid.momentum[n] += b.momentum[n];
          b.momentum[n].setZero();
        }
        if (with_force) {
          grid.force[n] += b.force[n];
          b.force[n].setZero();
        }
      }
    }
  }

 private:
  struct Buffer {
    std::vector<double> mass;
    std::vector<Vec<D>> momentum;
    std::vector<Vec<D>> force;
  };
  std::vector<Buffer> buffers_;
  std::vector<std::pair<long, long>> touched_, windows_;
};

}  // namespace pellicle
