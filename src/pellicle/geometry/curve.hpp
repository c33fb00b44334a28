#pragma once
//! Curves in 2D sampled into membrane points (IJNME §3: a membrane is a line of unconnected
//! material points, each standing for the length Δs between neighbours, m_p = ρ t Δs).

#include <functional>
#include <vector>

#include "pellicle/core/types.hpp"

namespace pellicle {

//! Points along a curve in order, and the length each point stands for.
struct SampledCurve {
  std::vector<Vec2> points;
  std::vector<double> lengths;  //!< Δs per point: the spacing (open curves: N Δs = L + Δs)
  bool closed = false;
};

//! How densely to sample: a target spacing, or an exact number of points.
struct Sampling {
  double spacing = 0.0;  //!< > 0: about this arc length between points
  int count = 0;         //!< > 0: exactly this many points (overrides spacing)
};

//! Sample x(u), u ∈ [0, 1], at equal arc-length steps Δs. Open curves include both ends (N
//! points, N − 1 gaps); closed curves do not repeat the start (N points, N gaps). Every
//! point stands for Δs, so the line density of material is exact along the curve; the shares
//! of an open curve's end points reach half a spacing past its ends. (The seeds' spring
//! confirms this: its 10 points over L = 0.3 weigh ρ A L/9 each, IJNME §3.1.1.)
SampledCurve sample_curve(const std::function<Vec2(double)>& x, bool closed, Sampling sampling);

SampledCurve sample_polyline(const std::vector<Vec2>& vertices, bool closed, Sampling sampling);
//! Arc of a circle (or ellipse with semi-axes a, b) from angle `from` to `to` (radians,
//! counter-clockwise); a full turn gives a closed curve.
SampledCurve sample_ellipse_arc(const Vec2& center, const Vec2& semi_axes, double from, double to,
                                Sampling sampling);
//! Centripetal Catmull–Rom spline through the given points.
SampledCurve sample_spline(const std::vector<Vec2>& through, bool closed, Sampling sampling);

}  // namespace pellicle
