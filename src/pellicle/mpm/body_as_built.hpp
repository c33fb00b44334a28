#pragma once
//! One body's per-point records in the order its points were built. A distributed run's
//! migration reorders and spreads a body's points over the ranks; what needs the whole body
//! in its generation order (membrane frames, the volume a membrane encloses)
//! gathers it by each point's column_names::body_index.

#include <algorithm>
#include <vector>

#include "pellicle/core/collective.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

//! `width` doubles per point of a body (this rank's points of it: [begin, end)), written by
//! append(point, out), which appends them; the whole body's, in the order its points were
//! built: from this rank's points alone when `ranks` is null, else from every rank's, on
//! every rank. Collective when `ranks` is set.
template <int D, class Append>
std::vector<double> body_as_built(const Particles<D>& points, long begin, long end, int width,
                                  Append&& append, const Collective* ranks) {
  std::vector<double> mine;
  mine.reserve((end - begin) * (width + 1));
  if (!ranks) {
    for (long p = begin; p < end; ++p) append(p, mine);
    return mine;
  }
  const auto& index = points.template named<double>(column_names::body_index);
  for (long p = begin; p < end; ++p) {
    mine.push_back(index[p]);
    append(p, mine);
  }
  const std::vector<double> all = ranks->all_gather(mine);
  std::vector<double> out(all.size() / (width + 1) * width);
  for (std::size_t r = 0; r < all.size(); r += width + 1) {
    const long i = static_cast<long>(all[r]);
    std::copy_n(all.data() + r + 1, width, out.data() + i * width);
  }
  return out;
}

}  // namespace pellicle
