#pragma once
//! The connected parts of a point cloud: points are linked when one lies in the other's
//! neighbourhood S_i (within h). A closed surface is one part; a neck that pinches off, or
//! two surfaces apart, make two (Suchde & Kuhnert §3.6 counts such parts as chambers).

#include "pellicle/pointcloud/neighbour_search.hpp"

namespace pellicle {

//! How many connected parts the neighbour graph has (0 for an empty cloud), with the links
//! of `more` too when given (S_i^ext beside S_i).
int connected_parts(const NeighbourLists& neighbours, const NeighbourLists* more = nullptr);

}  // namespace pellicle
