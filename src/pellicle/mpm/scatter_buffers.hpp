#pragma once
//! Race-free scatter to the grid with OpenMP: thread 0 writes into the grid itself, every
//! other thread into a private copy of the node fields; the copies are summed into the grid
//! over the node range each thread touched, and left zeroed for the next scatter.

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

template <int D>
class ScatterBuffers {
 public:
  //! Node fields thread `t` writes into.
  NodeFields<D> fields(int t, Grid<D>& grid) {
    if (t == 0) return {grid.mass.data(), grid.momentum.data(), grid.force.data()};
    Buffer& b = buffers_[t - 1];
    return {b.mass.data(), b.momentum.data(), b.force.data()};
  }

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
  }

  //! Record the node range [lo, hi] thread t wrote to.
  void touched(int t, long lo, long hi) { touched_[t] = {lo, hi}; }

  //! Sum the private copies into the grid and zero them again.
  void reduce(Grid<D>& grid, bool with_mass, bool with_momentum, bool with_force) {
    for (int t = 1; t < static_cast<int>(touched_.size()); ++t) {
      Buffer& b = buffers_[t - 1];
      const long lo = touched_[t].first, hi = touched_[t].second;
#pragma omp parallel for schedule(static)
      for (long n = lo; n <= hi; ++n) {
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
  std::vector<std::pair<long, long>> touched_;
};

}  // namespace pellicle
