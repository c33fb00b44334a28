#pragma once
//! Disjoint sets of the integers 0 … n−1 (union–find with path halving), each set named by
//! its smallest member: connected parts of a neighbour graph, chambers joined by contact.

#include <algorithm>
#include <numeric>
#include <vector>

namespace pellicle {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  //! The smallest member of a's set.
  int root(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  //! Join the sets of a and b; false when they were one already.
  bool join(int a, int b) {
    a = root(a);
    b = root(b);
    if (a == b) return false;
    parent_[std::max(a, b)] = std::min(a, b);
    return true;
  }

 private:
  std::vector<int> parent_;
};

}  // namespace pellicle
