#pragma once
//! Regions chosen by name from user input (`shape = "disk"` …). Adding a shape is its class
//! in region.cpp and one line in the table of region_factory.cpp.
//!
//! Keys of a region table (lengths in the case's length unit):
//!   shape = "box"           lower, upper
//!   shape = "disk"          center, radius          (2D)
//!   shape = "sphere"        center, radius          (3D)
//!   shape = "ellipse"       center, semi_axes       (2D)
//!   shape = "ellipsoid"     center, semi_axes       (3D)
//!   shape = "cylinder"      center, axis, radius, height  (3D, solid)
//!   shape = "half-space"    point, normal           (inside: (x − point)·normal ≤ 0)
//!   shape = "polygon"       vertices = [[x, y], …]  (2D)
//!   shape = "union" | "intersection" | "difference"   parts = [ {region}, … ]
//!                           (difference: the first part minus all the others)

#include <string>
#include <vector>

#include "pellicle/core/parameters.hpp"
#include "pellicle/geometry/region.hpp"

namespace pellicle {

//! Read a region from its table; problems are recorded in the reader (never null).
template <int D>
RegionPtr<D> make_region(ParameterReader& in);

//! Shape names valid in D dimensions.
template <int D>
std::vector<std::string> region_shapes();

}  // namespace pellicle
