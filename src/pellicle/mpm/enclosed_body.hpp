#pragma once
//! A body filling a membrane's inside (the gas of a bag, thesis ch. 6) and what is measured of
//! the pair while it runs: the volume the membrane encloses, its mean tension, and how many
//! of the filling body's points have left it (a bag that holds its gas keeps that at 0).

#include <string>
#include <vector>

#include "pellicle/core/collective.hpp"
#include "pellicle/geometry/enclosure.hpp"
#include "pellicle/geometry/membrane_geometry.hpp"
#include "pellicle/mpm/materials/material.hpp"
#include "pellicle/mpm/particles.hpp"

namespace pellicle {

template <int D>
struct EnclosedBody {
  int membrane = -1, filler = -1;     //!< body indices
  MembraneConnectivity connectivity;  //!< of the membrane's points, as generated
  std::vector<MirrorPlane> mirrors;   //!< wall and symmetry faces that close it
  double tolerance = 0.0;             //!< how near a face an open end must be
  double thickness = 0.0;             //!< of the membrane (tension = stress × thickness)
};

//! Volume the membrane encloses with the faces that close it: (1/D) ∮ (x − c)·n dA over the
//! membrane, with c on every mirror plane's axis at the plane, so the faces add nothing
//! (divergence theorem; exact for the polygon or triangle mesh through the points). In
//! axisymmetric runs 2π ∮ r²/2 dz, the volume of revolution (Pappus).
//! In a distributed run (`ranks` set) every rank calls these alike and gets the whole pair's
//! figure: the membrane is gathered in the order its points were built, sums are reduced.
template <int D>
double enclosed_volume(const Particles<D>& points, const EnclosedBody<D>& pair,
                       Kinematics kinematics, const Collective* ranks = nullptr);

//! Mean membrane tension: the in-surface stress (2D: t·σ·t; 3D: half the in-surface trace)
//! times thickness, averaged by mass.
template <int D>
double mean_tension(const Particles<D>& points, const EnclosedBody<D>& pair,
                    const Collective* ranks = nullptr);

//! Number of the filling body's points outside the membrane now.
template <int D>
long escaped_points(const Particles<D>& points, const EnclosedBody<D>& pair,
                    const Collective* ranks = nullptr);

}  // namespace pellicle
