#pragma once
//! Material points, stored as one array per quantity (structure of arrays). Points of one
//! body are contiguous: body b owns [bodies[b].begin, bodies[b].end). Every point has the
//! common columns below; a quantity only some models need (strain, frames, internal energy,
//! the APIC affine velocity, plastic strain) is a column its model declares (PointColumns).

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "pellicle/core/types.hpp"
#include "pellicle/mpm/point_columns.hpp"
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
  //! From this time on the body carries no stress (a tether cut, thesis §6.3); its points
  //! keep their mass and move with the grid.
  double cut_at = std::numeric_limits<double>::infinity();
  //! Points the body was built with, on all ranks together: a distributed run's ranks each
  //! hold some of them, numbered by column_names::body_index.
  long built = 0;
  //! The velocity its first point was built with: a rigid body's, on every rank.
  Vec<D> start_velocity = Vec<D>::Zero();
  long count() const { return end - begin; }
};

//! Names of the columns that more than one model reads.
namespace column_names {
inline constexpr const char* strain = "strain";    //!< accumulated small strain Σ Δε
inline constexpr const char* normal = "normal";    //!< membrane frame: unit normal
inline constexpr const char* tangent = "tangent";  //!< membrane frame: unit tangent (3D: t1)
//! Specific internal energy e of thermal models (fluids).
inline constexpr const char* internal_energy = "internal_energy";
//! Kinetic energy per unit mass the transfers removed from a point's motion in its last
//! to_points (APIC), which thermal models add to e (docs/theory/gas.md).
inline constexpr const char* transfer_heat = "transfer_heat";
//! A distributed run's index of each point in its body as built: migration reorders a rank's
//! points, and membrane frames and probes find points by it.
inline constexpr const char* body_index = "body_index";
}  // namespace column_names

template <int D>
struct Particles {
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<double> mass;
  std::vector<double> volume;   //!< current volume (2D: per unit depth; axisymmetric: 2πr × area)
  std::vector<double> density;  //!< current density, updated by continuity (IJNME eq 17)
  std::vector<Sym<D>> stress;   //!< Cauchy stress
  std::vector<int> body;        //!< body index of each point
  std::vector<BodyInfo<D>> bodies;
  PointColumns columns;  //!< the declared columns (point_columns.hpp)

  long size() const { return static_cast<long>(position.size()); }

  //! Declare a column of T = double, Vec<D>, Sym<D> or Mat<D> for every point (zero-filled).
  template <class T>
  Column<T> declare(const ColumnSpec& spec) {
    return columns.template declare<T>(spec, shape_of<T>(), size());
  }
  template <class T>
  std::vector<T>& operator[](Column<T> c) {
    return columns[c];
  }
  template <class T>
  const std::vector<T>& operator[](Column<T> c) const {
    return columns[c];
  }

  //! A declared column by name, for code outside the model that owns it (tests, validation
  //! problems). Throws std::out_of_range when no model declared it with that type.
  template <class T>
  std::vector<T>& named(const std::string& name) {
    return columns[checked<T>(name)];
  }
  template <class T>
  const std::vector<T>& named(const std::string& name) const {
    return columns[checked<T>(name)];
  }

  //! Room for `points` points in every column, so appending them allocates nothing more.
  void reserve(long points) {
    position.reserve(points);
    velocity.reserve(points);
    mass.reserve(points);
    density.reserve(points);
    volume.reserve(points);
    stress.reserve(points);
    body.reserve(points);
    columns.reserve(points);
  }

  //! Append one point of the body currently being built (the last in `bodies`); its declared
  //! columns start at zero.
  void add(const Vec<D>& x, const Vec<D>& v, double m, double rho) {
    position.push_back(x);
    velocity.push_back(v);
    mass.push_back(m);
    density.push_back(rho);
    volume.push_back(m / rho);
    stress.push_back(Sym<D>::Zero());
    body.push_back(static_cast<int>(bodies.size()) - 1);
    bodies.back().end = size();
    ++bodies.back().built;
    columns.resize(size());
  }

 private:
  template <class T>
  Column<T> checked(const std::string& name) const {
    const Column<T> c = columns.template find<T>(name);
    if (!c.valid()) throw std::out_of_range("no point column '" + name + "' of that type");
    return c;
  }
  template <class T>
  static constexpr ColumnShape shape_of() {
    if constexpr (std::is_same_v<T, double>)
      return ColumnShape::scalar;
    else if constexpr (std::is_same_v<T, Vec<D>>)
      return ColumnShape::vector;
    else if constexpr (std::is_same_v<T, Sym<D>>)
      return ColumnShape::symmetric;
    else {
      static_assert(std::is_same_v<T, Mat<D>>, "columns hold double, Vec<D>, Sym<D> or Mat<D>");
      return ColumnShape::matrix;
    }
  }
};

}  // namespace pellicle
