#include "pellicle/dist/migration.hpp"

#include <algorithm>
#include <cstring>

namespace pellicle {

namespace {

//! Every per-point array of the points, as (doubles per point, data): the common columns,
//! then the declared ones. The body index travels separately.
template <int D>
std::vector<std::pair<int, double*>> point_arrays(Particles<D>& p) {
  std::vector<std::pair<int, double*>> arrays = {{D, p.position.data()->data()},
                                                 {D, p.velocity.data()->data()},
                                                 {1, p.mass.data()},
                                                 {1, p.volume.data()},
                                                 {1, p.density.data()},
                                                 {kSymComponents<D>, p.stress.data()->data()}};
  for (int c = 0; c < p.columns.count(); ++c)
    arrays.push_back({p.columns.components(c), p.columns.data(c)});
  return arrays;
}

//! Resize every per-point array to n points (values kept up to the old size).
template <int D>
void resize_points(Particles<D>& p, long n) {
  p.position.resize(n);
  p.velocity.resize(n);
  p.mass.resize(n);
  p.volume.resize(n);
  p.density.resize(n);
  p.stress.resize(n);
  p.body.resize(n);
  p.columns.resize(n);
}

}  // namespace

template <int D>
long migrate_points(const Communicator& world, const std::vector<LeavingPoint>& leaving,
                    Particles<D>& points, const std::vector<int>* neighbours) {
  const long n = points.size();
  // A record per leaving point: its body, then every array's values.
  auto arrays = point_arrays(points);
  int record = 1;
  for (const auto& a : arrays) record += a.first;
  std::vector<std::vector<double>> to_rank(world.size()), from_rank;
  for (const auto& [p, rank] : leaving) {
    auto& out = to_rank[rank];
    out.push_back(points.body[p]);
    for (const auto& [c, data] : arrays) out.insert(out.end(), data + p * c, data + (p + 1) * c);
  }
  if (neighbours)
    world.neighbour_all_to_all(to_rank, from_rank, *neighbours);
  else
    world.all_to_all(to_rank, from_rank);
  long received = 0;
  for (const auto& in : from_rank) received += static_cast<long>(in.size()) / record;
  if (leaving.empty() && received == 0) return 0;

  // The layout changes by a few points, so points are moved, not the arrays rebuilt:
  // 1. in each body, the last points fill the places of the leaving ones;
  // 2. each body's kept block shifts to its new start by moving only the part of it that
  //    does not overlap its new place (bodies moving down first, in order, then those
  //    moving up, in reverse order, so no block lands on one not yet moved);
  // 3. the arrivals follow each body's kept block, by sender rank.
  const int bodies = static_cast<int>(points.bodies.size());
  std::vector<long> kept(bodies);
  struct Move {
    long from, to, count;
  };
  std::vector<Move> moves;
  std::size_t next = leaving.size();
  for (int b = bodies - 1; b >= 0; --b) {  // leaving is in ascending point order
    const long begin = points.bodies[b].begin;
    long end = points.bodies[b].end;
    while (next > 0 && leaving[next - 1].point >= begin) {
      const long p = leaving[--next].point;
      if (p != end - 1) moves.push_back({end - 1, p, 1});
      --end;
    }
    kept[b] = end - begin;
  }
  std::vector<std::vector<const double*>> arriving(bodies);
  for (const auto& in : from_rank)
    for (std::size_t r = 0; r < in.size(); r += record)
      arriving[static_cast<int>(in[r])].push_back(in.data() + r + 1);
  std::vector<long> start(bodies + 1, 0);
  for (int b = 0; b < bodies; ++b)
    start[b + 1] = start[b] + kept[b] + static_cast<long>(arriving[b].size());
  auto shift = [&](int b) {
    const long begin = points.bodies[b].begin, by = start[b] - begin;
    if (by > 0) {
      const long k = std::min(by, kept[b]);
      moves.push_back({begin, begin + by + kept[b] - k, k});
    } else if (by < 0) {
      const long k = std::min(-by, kept[b]);
      moves.push_back({begin + kept[b] - k, start[b], k});
    }
  };
  for (int b = 0; b < bodies; ++b)
    if (start[b] <= points.bodies[b].begin) shift(b);
  for (int b = bodies - 1; b >= 0; --b)
    if (start[b] > points.bodies[b].begin) shift(b);

  const long m = start[bodies];
  if (m > n) resize_points(points, m);
  int offset = 0;
  for (const auto& [c, data] : point_arrays(points)) {
    for (const Move& move : moves)
      std::memcpy(data + move.to * c, data + move.from * c, sizeof(double) * c * move.count);
    for (int b = 0; b < bodies; ++b)
      for (std::size_t a = 0; a < arriving[b].size(); ++a)
        std::memcpy(data + (start[b] + kept[b] + static_cast<long>(a)) * c, arriving[b][a] + offset,
                    sizeof(double) * c);
    offset += c;
  }
  if (m < n) resize_points(points, m);
  for (int b = 0; b < bodies; ++b) {
    points.bodies[b].begin = start[b];
    points.bodies[b].end = start[b + 1];
    std::fill(points.body.begin() + start[b], points.body.begin() + start[b + 1], b);
  }
  return static_cast<long>(leaving.size());
}

template long migrate_points<2>(const Communicator&, const std::vector<LeavingPoint>&,
                                Particles<2>&, const std::vector<int>*);
template long migrate_points<3>(const Communicator&, const std::vector<LeavingPoint>&,
                                Particles<3>&, const std::vector<int>*);

}  // namespace pellicle
