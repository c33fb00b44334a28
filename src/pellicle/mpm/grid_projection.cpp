#include "pellicle/mpm/grid_projection.hpp"

#include <omp.h>

#include <algorithm>
#include <type_traits>

namespace pellicle {
namespace {

enum BodyKind : unsigned char { kFluid = 1, kMembrane = 2 };

template <class T>
void zero_fill(std::vector<T>& v, long size) {
  if constexpr (std::is_same_v<T, double>)
    v.assign(size, 0.0);
  else
    v.assign(size, T::Zero());
}

}  // namespace

template <int D>
void GridProjection<D>::prepare(int threads, long nodes, int stencil) {
  // assign() reuses the storage once sized: no allocation after the first snapshot.
  sums_.resize(threads);
  for (Sums& s : sums_) {
    zero_fill(s.mass, nodes);
    zero_fill(s.fluid_mass, nodes);
    zero_fill(s.membrane_mass, nodes);
    zero_fill(s.fields.pressure, nodes);
    zero_fill(s.fields.stress, nodes);
    zero_fill(s.fields.membrane_stress, nodes);
  }
  block_nodes_.resize(threads * kBlock * stencil);
  block_weights_.resize(threads * kBlock * stencil);
}

template <int D>
const NodeStresses<D>& GridProjection<D>::project(const Simulation<D>& simulation) {
  const Particles<D>& points = simulation.points();
  const Grid<D>& grid = simulation.grid();
  const Transfer<D>& transfer = simulation.transfer();
  body_kind_.resize(points.bodies.size());
  for (std::size_t b = 0; b < points.bodies.size(); ++b) {
    const Material<D>& material = simulation.material(points.bodies[b].material);
    body_kind_[b] = (material.is_fluid() ? kFluid : 0) | (material.is_membrane() ? kMembrane : 0);
  }
  const long n = points.size(), nodes = grid.node_count();
  const int stencil = transfer.stencil_size();
  prepare(omp_get_max_threads(), nodes, stencil);

  const long blocks = (n + kBlock - 1) / kBlock;
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    Sums& s = sums_[t];
    long* const ids = block_nodes_.data() + t * kBlock * stencil;
    double* const weights = block_weights_.data() + t * kBlock * stencil;
#pragma omp for schedule(static)
    for (long block = 0; block < blocks; ++block) {
      const long begin = block * kBlock, end = std::min(n, begin + kBlock);
      transfer.node_weights(points, grid, begin, end, ids, weights);
      for (long p = begin; p < end; ++p) {
        const unsigned char kind = body_kind_[points.body[p]];
        const Sym<D>& sigma = points.stress[p];
        const double pressure = -trace<D>(sigma) / 3.0;
        const long* id = ids + (p - begin) * stencil;
        const double* w = weights + (p - begin) * stencil;
        for (int k = 0; k < stencil; ++k) {
          const long i = id[k];
          const double wm = w[k] * points.mass[p];
          s.mass[i] += wm;
          s.fields.stress[i] += wm * sigma;
          if (kind & kFluid) {
            s.fluid_mass[i] += wm;
            s.fields.pressure[i] += wm * pressure;
          }
          if (kind & kMembrane) {
            s.membrane_mass[i] += wm;
            s.fields.membrane_stress[i] += wm * sigma;
          }
        }
      }
    }
  }

  // Add the other threads' sums to thread 0's (in thread order), complete the sums of nodes
  // other ranks share (a distributed run), then divide by the masses.
  Sums& total = sums_[0];
  NodeStresses<D>& mean = total.fields;
  if (sums_.size() > 1) {
#pragma omp parallel for schedule(static)
    for (long i = 0; i < nodes; ++i) {
      for (std::size_t t = 1; t < sums_.size(); ++t) {
        const Sums& s = sums_[t];
        total.mass[i] += s.mass[i];
        total.fluid_mass[i] += s.fluid_mass[i];
        total.membrane_mass[i] += s.membrane_mass[i];
        mean.pressure[i] += s.fields.pressure[i];
        mean.stress[i] += s.fields.stress[i];
        mean.membrane_stress[i] += s.fields.membrane_stress[i];
      }
    }
  }
  simulation.complete_node_sums({{total.mass.data(), 1},
                                 {total.fluid_mass.data(), 1},
                                 {total.membrane_mass.data(), 1},
                                 {mean.pressure.data(), 1},
                                 {mean.stress.data()->data(), kSymComponents<D>},
                                 {mean.membrane_stress.data()->data(), kSymComponents<D>}});
#pragma omp parallel for schedule(static)
  for (long i = 0; i < nodes; ++i) {
    if (total.mass[i] > 0.0) mean.stress[i] /= total.mass[i];
    if (total.fluid_mass[i] > 0.0) mean.pressure[i] /= total.fluid_mass[i];
    if (total.membrane_mass[i] > 0.0) mean.membrane_stress[i] /= total.membrane_mass[i];
  }
  return mean;
}

template class GridProjection<2>;
template class GridProjection<3>;

}  // namespace pellicle
