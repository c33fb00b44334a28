#include "pellicle/pointcloud/cell_groups.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace pellicle {

template <int D>
CellGroups<D>::CellGroups(const std::vector<Vec<D>>& x, long begin, long end, const Vec<D>& origin,
                          double h)
    : origin_(origin), h_(h) {
  const long n = end - begin;
  std::vector<std::pair<std::int64_t, long>> keyed(n);
  std::vector<IVec<D>> cell_of_point(n);
  for (long i = 0; i < n; ++i) {
    IVec<D> c;
    for (int d = 0; d < D; ++d) {
      const double cell = std::floor((x[begin + i][d] - origin[d]) / h);
      if (!(std::abs(cell) < 1073741824.0))  // also NaN: its cast to int is undefined
        throw std::invalid_argument("point " + std::to_string(begin + i) +
                                    ": coordinate not finite or more than 2^30 cells from the "
                                    "grid origin");
      c[d] = static_cast<int>(cell);
    }
    cell_of_point[i] = c;
    keyed[i] = {key(c), begin + i};
  }
  std::sort(keyed.begin(), keyed.end());
  order_.resize(n);
  for (long i = 0; i < n; ++i) {
    order_[i] = keyed[i].second;
    if (i == 0 || keyed[i].first != keyed[i - 1].first) {
      index_[keyed[i].first] = static_cast<int>(cells_.size());
      cells_.push_back(cell_of_point[keyed[i].second - begin]);
      starts_.push_back(i);
    }
  }
  starts_.push_back(n);
}

template class CellGroups<2>;
template class CellGroups<3>;

}  // namespace pellicle
