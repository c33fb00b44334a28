#include "pellicle/mpm/cell_field.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "pellicle/core/bspline.hpp"

namespace pellicle {

namespace {

//! Cell index along axis d after reflection at a constrained face; −1 beyond a free face.
template <int D>
int fold_cell(const Grid<D>& grid, int d, int i) {
  const int cells = grid.cells()[d];
  if (i < 0) return grid.faces()[2 * d] == FaceCondition::free ? -1 : -1 - i;
  if (i >= cells) return grid.faces()[2 * d + 1] == FaceCondition::free ? -1 : 2 * cells - 1 - i;
  return i;
}

//! Flat index of cell (i, j[, k]) after folding, or −1.
template <int D>
long fold_flat(const Grid<D>& grid, const int* index) {
  long flat = 0, stride = 1;
  for (int d = 0; d < D; ++d) {
    const int c = fold_cell(grid, d, index[d]);
    if (c < 0) return -1;
    flat += c * stride;
    stride *= grid.cells()[d];
  }
  return flat;
}

}  // namespace

template <int D>
long cell_count(const Grid<D>& grid) {
  long n = 1;
  for (int d = 0; d < D; ++d) n *= grid.cells()[d];
  return n;
}

template <int D>
long containing_cell(const Grid<D>& grid, const Vec<D>& x) {
  long flat = 0, stride = 1;
  for (int d = 0; d < D; ++d) {
    const int c = std::clamp(static_cast<int>(std::floor((x[d] - grid.lower()[d]) / grid.cell())),
                             0, grid.cells()[d] - 1);
    flat += c * stride;
    stride *= grid.cells()[d];
  }
  return flat;
}

template <int D>
void spread_to_cells(const Grid<D>& grid, const std::vector<Vec<D>>& positions,
                     const std::vector<double>& weight, long begin, long end,
                     std::vector<double>& cells, CellSpreadCopies& work,
                     const std::vector<char>* from) {
  const double inv_h = 1.0 / grid.cell();
  long cell_strides[D];
  cell_strides[0] = 1;
  for (int d = 1; d < D; ++d) cell_strides[d] = cell_strides[d - 1] * grid.cells()[d - 1];
  // Thread 0 adds into `cells`, the others into private copies summed at the end: no
  // atomics in the point loop.
  const int threads = omp_get_max_threads();
  auto& partial = work.copies;
  if (static_cast<int>(partial.size()) != threads - 1 ||
      (threads > 1 && partial[0].size() != cells.size()))
    partial.assign(threads - 1, std::vector<double>(cells.size(), 0.0));
  work.written.assign(partial.size(), {0, -1});
  // The grid's values in locals: the stores into the cells could otherwise, for all the
  // compiler knows, change them.
  const Vec<D> lower = grid.lower();
  const char* spread_from = from != nullptr ? from->data() : nullptr;
  int cells_along[D];
  long reach = 0;  // flat offset from a point's first cell to its last
  for (int d = 0; d < D; ++d) {
    cells_along[d] = grid.cells()[d];
    reach += 2 * cell_strides[d];
  }
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    double* out = t == 0 ? cells.data() : partial[t - 1].data();
    long first = std::numeric_limits<long>::max(), last = -1;  // cells this thread writes
#pragma omp for schedule(static) nowait
    for (long p = begin; p < end; ++p) {
      // Cell-centre coordinates: centre c sits at c + ½ cells from the lower corner.
      const Vec<D> x = positions[p];
      double u[D];
      int base[D];
      long first_cell = 0;  // in `from`: shifted by one per axis
      bool listed = true;   // the first cell is one `from` holds (not so on the upper faces)
      for (int d = 0; d < D; ++d) {
        u[d] = (x[d] - lower[d]) * inv_h - 0.5;
        base[d] = quadratic_bspline_first(u[d]);
        first_cell += (base[d] + 1) * cell_strides[d];
        listed = listed && base[d] >= -1 && base[d] + 1 < cells_along[d];
      }
      if (spread_from != nullptr && listed && !spread_from[first_cell]) continue;
      double w[D][3], dw[3];
      bool interior = true;  // all 3^D cells inside the domain: nothing to fold
      for (int d = 0; d < D; ++d) {
        quadratic_bspline_weights(u[d], base[d], w[d], dw);
        interior = interior && base[d] >= 0 && base[d] + 2 < cells_along[d];
      }
      // A cell's value is weight · Π_d w_d, multiplied in axis order.
      double weighted[3];
      for (int i = 0; i < 3; ++i) weighted[i] = weight[p] * w[0][i];
      if (interior) {
        long corner = 0;
        for (int d = 0; d < D; ++d) corner += base[d] * cell_strides[d];
        first = std::min(first, corner), last = std::max(last, corner + reach);
        for (int k = 0; k < (D == 3 ? 3 : 1); ++k)
          for (int j = 0; j < 3; ++j) {
            double* row = out + corner + j * cell_strides[1];
            if constexpr (D == 3) row += k * cell_strides[D - 1];
            for (int i = 0; i < 3; ++i) {
              double value = weighted[i] * w[1][j];
              if constexpr (D == 3) value *= w[D - 1][k];
              row[i] += value;
            }
          }
        continue;
      }
      // Each axis's three cells folded at the faces once per point (offset along the flat
      // index; −1 beyond a free face), not once per cell of the 3^D.
      long axis_offset[D][3];
      long lowest = 0, highest = 0;  // the first and last cell written
      bool writes = true;
      for (int d = 0; d < D; ++d) {
        long low = std::numeric_limits<long>::max(), high = -1;
        for (int i = 0; i < 3; ++i) {
          const int c = fold_cell(grid, d, base[d] + i);
          axis_offset[d][i] = c < 0 ? -1 : c * cell_strides[d];
          if (c >= 0)
            low = std::min(low, axis_offset[d][i]), high = std::max(high, axis_offset[d][i]);
        }
        writes = writes && high >= 0;
        if (writes) lowest += low, highest += high;
      }
      if (writes) first = std::min(first, lowest), last = std::max(last, highest);
      for (int k = 0; k < (D == 3 ? 3 : 1); ++k)
        for (int j = 0; j < 3; ++j) {
          const long across = D == 3 ? axis_offset[D - 1][k] : 0;
          if (axis_offset[1][j] < 0 || across < 0) continue;
          const long row = axis_offset[1][j] + across;
          for (int i = 0; i < 3; ++i) {
            if (axis_offset[0][i] < 0) continue;
            double value = weighted[i] * w[1][j];
            if constexpr (D == 3) value *= w[D - 1][k];
            out[row + axis_offset[0][i]] += value;
          }
        }
    }
    if (t > 0) work.written[t - 1] = {first, last};
  }
  // Each copy is zero outside the cells its thread wrote to.
  for (std::size_t t = 0; t < partial.size(); ++t) {
    std::vector<double>& copy = partial[t];
    const auto [first, last] = work.written[t];
#pragma omp parallel for schedule(static)
    for (long c = first; c <= last; ++c) {
      cells[c] += copy[c];
      copy[c] = 0.0;
    }
  }
}

template <int D>
void cells_spread_from(const Grid<D>& grid, const std::vector<double>& reads,
                       std::vector<char>& from) {
  // A point with first cell f per axis spreads to f, f + 1, f + 2. For f in [−1, cells − 2]
  // (every point inside the domain but those on an upper face, which spread_to_cells always
  // spreads) folding maps only −1 onto 0 and `cells` onto cells − 1, so the points that reach
  // cell c after folding are those with f in [c − 2, c] per axis.
  const long count = cell_count(grid);
  from.resize(count);
#pragma omp parallel for schedule(static)
  for (long c = 0; c < count; ++c) from[c] = 0;
#pragma omp parallel for schedule(static)
  for (long c = 0; c < count; ++c) {
    if (!(reads[c] > 0.0)) continue;
    long rest = c, low[D], high[D], stride[D];
    for (int d = 0; d < D; ++d) {
      const long n = grid.cells()[d], index = rest % n;
      rest /= n;
      stride[d] = d == 0 ? 1 : stride[d - 1] * grid.cells()[d - 1];
      low[d] = std::max(index - 2, -1L) + 1;  // shifted by one
      high[d] = std::min(index, n - 2) + 1;
    }
    for (long k = D == 3 ? low[D - 1] : 0; k <= (D == 3 ? high[D - 1] : 0); ++k)
      for (long j = low[1]; j <= high[1]; ++j)
        for (long i = low[0]; i <= high[0]; ++i) {
          const long f = i + j * stride[1] + (D == 3 ? k * stride[D - 1] : 0);
#pragma omp atomic write
          from[f] = 1;
        }
  }
}

template <int D>
void cells_around_node(const Grid<D>& grid, long node, long (&cells)[1 << D]) {
  // Node (I, J[, K]) of the domain touches cells I−1 and I along each axis.
  const IVec<D> index = grid.unflatten(node);
  for (int corner = 0; corner < (1 << D); ++corner) {
    int cell[D];
    for (int d = 0; d < D; ++d) cell[d] = index[d] - Grid<D>::kGhost - 1 + ((corner >> d) & 1);
    cells[corner] = fold_flat(grid, cell);
  }
}

template <int D>
Vec<D> cell_gradient_at_node(const Grid<D>& grid, const std::vector<double>& cells, long node) {
  long around[1 << D];
  cells_around_node(grid, node, around);
  Vec<D> gradient = Vec<D>::Zero();
  for (int corner = 0; corner < (1 << D); ++corner) {
    const double value = around[corner] < 0 ? 0.0 : cells[around[corner]];
    for (int d = 0; d < D; ++d) gradient[d] += ((corner >> d) & 1 ? value : -value);
  }
  return gradient / ((1 << (D - 1)) * grid.cell());
}

template long cell_count<2>(const Grid<2>&);
template long cell_count<3>(const Grid<3>&);
template long containing_cell<2>(const Grid<2>&, const Vec<2>&);
template long containing_cell<3>(const Grid<3>&, const Vec<3>&);
template void spread_to_cells<2>(const Grid<2>&, const std::vector<Vec<2>>&,
                                 const std::vector<double>&, long, long, std::vector<double>&,
                                 CellSpreadCopies&, const std::vector<char>*);
template void spread_to_cells<3>(const Grid<3>&, const std::vector<Vec<3>>&,
                                 const std::vector<double>&, long, long, std::vector<double>&,
                                 CellSpreadCopies&, const std::vector<char>*);
template void cells_spread_from<2>(const Grid<2>&, const std::vector<double>&, std::vector<char>&);
template void cells_spread_from<3>(const Grid<3>&, const std::vector<double>&, std::vector<char>&);
template void cells_around_node<2>(const Grid<2>&, long, long (&)[4]);
template void cells_around_node<3>(const Grid<3>&, long, long (&)[8]);
template Vec<2> cell_gradient_at_node<2>(const Grid<2>&, const std::vector<double>&, long);
template Vec<3> cell_gradient_at_node<3>(const Grid<3>&, const std::vector<double>&, long);

}  // namespace pellicle
