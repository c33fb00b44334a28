#include "pellicle/dist/migration.hpp"

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

//! Where a point of the new order comes from: a point of this rank, or a received record
//! (its values after the body index).
struct PointSource {
  long point;
  const double* data;
};

//! Lay the points out in `order`; body b takes [first[b], first[b + 1]).
template <int D>
void rebuild(const std::vector<PointSource>& order, const std::vector<long>& first,
             Particles<D>& points) {
  const long n = points.size(), m = static_cast<long>(order.size());
  if (m > n) resize_points(points, m);
  std::vector<double> scratch;
  int offset = 0;
  for (const auto& [c, data] : point_arrays(points)) {
    scratch.resize(static_cast<std::size_t>(m) * c);
    for (long q = 0; q < m; ++q) {
      const double* from = order[q].point >= 0 ? data + order[q].point * c : order[q].data + offset;
      std::memcpy(scratch.data() + q * c, from, sizeof(double) * c);
    }
    std::memcpy(data, scratch.data(), sizeof(double) * scratch.size());
    offset += c;
  }
  if (m < n) resize_points(points, m);
  for (std::size_t b = 0; b < points.bodies.size(); ++b) {
    points.bodies[b].begin = first[b];
    points.bodies[b].end = first[b + 1];
    std::fill(points.body.begin() + first[b], points.body.begin() + first[b + 1],
              static_cast<int>(b));
  }
}

}  // namespace

template <int D>
void keep_points(const std::vector<char>& keep, Particles<D>& points) {
  std::vector<PointSource> order;
  std::vector<long> first(points.bodies.size() + 1, 0);
  for (std::size_t b = 0; b < points.bodies.size(); ++b) {
    first[b] = static_cast<long>(order.size());
    for (long p = points.bodies[b].begin; p < points.bodies[b].end; ++p)
      if (keep[p]) order.push_back({p, nullptr});
  }
  first.back() = static_cast<long>(order.size());
  rebuild(order, first, points);
}

template <int D>
long migrate_points(const Communicator& world, const std::vector<int>& destination,
                    Particles<D>& points) {
  const int me = world.rank();
  const long n = points.size();
  // A record per leaving point: its body, then every array's values.
  auto arrays = point_arrays(points);
  int record = 1;
  for (const auto& a : arrays) record += a.first;
  std::vector<std::vector<double>> to_rank(world.size()), from_rank;
  long sent = 0;
  for (long p = 0; p < n; ++p) {
    if (destination[p] == me) continue;
    auto& out = to_rank[destination[p]];
    out.push_back(points.body[p]);
    for (const auto& [c, data] : arrays) out.insert(out.end(), data + p * c, data + (p + 1) * c);
    ++sent;
  }
  world.all_to_all(to_rank, from_rank);
  long received = 0;
  for (const auto& in : from_rank) received += static_cast<long>(in.size()) / record;
  if (sent == 0 && received == 0) return 0;

  // The new order: per body, its kept points, then its arrivals by sender rank.
  std::vector<PointSource> order;
  order.reserve(n - sent + received);
  std::vector<long> first(points.bodies.size() + 1, 0);
  for (std::size_t b = 0; b < points.bodies.size(); ++b) {
    first[b] = static_cast<long>(order.size());
    for (long p = points.bodies[b].begin; p < points.bodies[b].end; ++p)
      if (destination[p] == me) order.push_back({p, nullptr});
    for (const auto& in : from_rank)
      for (std::size_t r = 0; r < in.size(); r += record)
        if (static_cast<std::size_t>(in[r]) == b) order.push_back({-1, in.data() + r + 1});
  }
  first.back() = static_cast<long>(order.size());
  rebuild(order, first, points);
  return sent;
}

template void keep_points<2>(const std::vector<char>&, Particles<2>&);
template void keep_points<3>(const std::vector<char>&, Particles<3>&);
template long migrate_points<2>(const Communicator&, const std::vector<int>&, Particles<2>&);
template long migrate_points<3>(const Communicator&, const std::vector<int>&, Particles<3>&);

}  // namespace pellicle
