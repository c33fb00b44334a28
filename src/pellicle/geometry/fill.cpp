#include "pellicle/geometry/fill.hpp"

namespace pellicle {

template <int D>
std::vector<Vec<D>> fill_region(const Region<D>& region, const Vec<D>& lower, const Vec<D>& upper,
                                double h, int n) {
  std::vector<Vec<D>> points;
  for_each_fill_point<D>(region, lower, upper, h, n, [&](const Vec<D>& x) { points.push_back(x); });
  return points;
}

template std::vector<Vec<2>> fill_region<2>(const Region<2>&, const Vec<2>&, const Vec<2>&, double,
                                            int);
template std::vector<Vec<3>> fill_region<3>(const Region<3>&, const Vec<3>&, const Vec<3>&, double,
                                            int);

}  // namespace pellicle
