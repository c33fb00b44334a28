#pragma once
//! The orientation sweep every unconnected-point algorithm shares (Suchde & Kuhnert §3.2;
//! the membrane frames' `propagate` orientation): points are visited breadth-first through
//! their neighbourhoods, and each point reached takes the side of the point it was reached
//! from. The sweep starts from the seeds (points whose side is settled) as one front, then
//! from the first unvisited point of each piece the seeds did not reach. How neighbours are
//! found and what "taking the side" does are the caller's: normals/ searches cells around a
//! point and flips a normal vector, surface/ walks its neighbour lists and flips a frame.

#include <cstdint>
#include <deque>
#include <vector>

namespace pellicle {

//! Sweep points [begin, end). `for_each_neighbour(p, visit)` calls `visit(q)` for every
//! neighbour q of p (any order, p itself allowed); `take_side(from, to)` makes point `to`
//! agree with `from`; `on_piece(points)` receives the points of each connected piece in the
//! order they were reached (the seeds' front counts as one piece).
template <class ForEachNeighbour, class TakeSide, class OnPiece>
void orientation_sweep(long begin, long end, const std::vector<long>& seeds,
                       ForEachNeighbour&& for_each_neighbour, TakeSide&& take_side,
                       OnPiece&& on_piece) {
  std::vector<std::uint8_t> visited(end - begin, 0);
  std::deque<long> queue;
  std::vector<long> piece;
  auto spread = [&] {
    while (!queue.empty()) {
      const long p = queue.front();
      queue.pop_front();
      piece.push_back(p);
      for_each_neighbour(p, [&](long q) {
        if (visited[q - begin]) return;
        visited[q - begin] = 1;
        take_side(p, q);
        queue.push_back(q);
      });
    }
    on_piece(piece);
    piece.clear();
  };
  if (!seeds.empty()) {
    for (long s : seeds) visited[s - begin] = 1, queue.push_back(s);
    spread();
  }
  for (long start = begin; start < end; ++start) {
    if (visited[start - begin]) continue;
    visited[start - begin] = 1;
    queue.push_back(start);
    spread();
  }
}

}  // namespace pellicle
