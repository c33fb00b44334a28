#include "pellicle/geometry/fill.hpp"

#include <algorithm>
#include <cmath>

namespace pellicle {

template <int D>
std::vector<Vec<D>> fill_region(const Region<D>& region, const Vec<D>& lower, const Vec<D>& upper,
                                double h, int n) {
  const Box<D> b = region.bounds();
  IVec<D> first, last;
  for (int d = 0; d < D; ++d) {
    const int cells = static_cast<int>(std::lround((upper[d] - lower[d]) / h));
    const double lo = std::max(b.lower[d], lower[d]), hi = std::min(b.upper[d], upper[d]);
    first[d] = std::clamp(static_cast<int>(std::floor((lo - lower[d]) / h)), 0, cells);
    last[d] = std::clamp(static_cast<int>(std::ceil((hi - lower[d]) / h)), 0, cells);
  }
  std::vector<Vec<D>> points;
  if ((first.array() >= last.array()).any()) return points;
  const double sub = h / n;
  IVec<D> cell = first;
  while (true) {
    for (int k = 0; k < static_cast<int>(std::pow(n, D)); ++k) {
      Vec<D> x;
      int rest = k;
      for (int d = 0; d < D; ++d) {
        x[d] = lower[d] + cell[d] * h + (rest % n + 0.5) * sub;
        rest /= n;
      }
      if (region.contains(x)) points.push_back(x);
    }
    int d = 0;
    for (; d < D; ++d) {
      if (++cell[d] < last[d]) break;
      cell[d] = first[d];
    }
    if (d == D) break;
  }
  return points;
}

template std::vector<Vec<2>> fill_region<2>(const Region<2>&, const Vec<2>&, const Vec<2>&, double,
                                            int);
template std::vector<Vec<3>> fill_region<3>(const Region<3>&, const Vec<3>&, const Vec<3>&, double,
                                            int);

}  // namespace pellicle
