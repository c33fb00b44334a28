#pragma once
//! Material points, stored as one array per quantity (structure of arrays). Points of one
//! body are contiguous: body b owns [bodies[b].begin, bodies[b].end).

#include <memory>
#include <string>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/normals/frame_estimator.hpp"

namespace pellicle {

//! What the solver knows about a body beyond its points.
template <int D>
struct BodyInfo {
  std::string name;
  int material = 0;                              //!< index into the simulation's materials
  Vec<D> applied_acceleration = Vec<D>::Zero();  //!< external force / body mass
  long begin = 0, end = 0;                       //!< point range
  //! Membrane bodies: how their points' frames are estimated; null for solids.
  std::shared_ptr<FrameEstimator<D>> frames;
  long count() const { return end - begin; }
};

template <int D>
struct Particles {
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<double> mass;
  std::vector<double> volume;   //!< current volume (2D: per unit depth; axisymmetric: 2πr × area)
  std::vector<double> density;  //!< current density, updated by continuity (IJNME eq 17)
  std::vector<Sym<D>> stress;   //!< Cauchy stress
  std::vector<Sym<D>> strain;   //!< accumulated small strain Σ Δε
  std::vector<double> energy;   //!< specific internal energy e (fluids; 0 for solids)
  std::vector<Mat<D>> affine;   //!< APIC affine velocity C_p (only sized when APIC is used)
  std::vector<Vec<D>> normal;   //!< membrane points: unit normal of the local frame (else 0)
  std::vector<Vec<D>> tangent;  //!< membrane points: unit tangent (3D: t1; t2 = n × t1)
  std::vector<int> body;        //!< body index of each point
  std::vector<BodyInfo<D>> bodies;

  long size() const { return static_cast<long>(position.size()); }

  //! Append one point of the body currently being built (the last in `bodies`).
  void add(const Vec<D>& x, const Vec<D>& v, double m, double rho, const Sym<D>& s,
           const Sym<D>& e) {
    position.push_back(x);
    velocity.push_back(v);
    mass.push_back(m);
    density.push_back(rho);
    volume.push_back(m / rho);
    stress.push_back(s);
    strain.push_back(e);
    energy.push_back(0.0);
    normal.push_back(Vec<D>::Zero());
    tangent.push_back(Vec<D>::Zero());
    body.push_back(static_cast<int>(bodies.size()) - 1);
    bodies.back().end = size();
  }
};

}  // namespace pellicle
