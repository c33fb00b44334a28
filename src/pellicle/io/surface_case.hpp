#pragma once
//! A surface case file read, checked and typed (Suchde & Kuhnert problems): the shape and
//! its initial cloud, the velocity formulas, the PDE, the step settings and the output.
//! A case is a surface case when it has a `[surface]` table instead of `[grid]`. Every key
//! is documented in docs/user-guide.md ("Surface cases").

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "pellicle/geometry/surface_shape.hpp"
#include "pellicle/io/case.hpp"
#include "pellicle/surface/simulation.hpp"

namespace pellicle {

//! One surface of a case: its name (contact rules and output refer to it) and its shape.
template <int D>
struct NamedSurface {
  std::string name;
  SurfaceShapePtr<D> shape;
};

template <int D>
struct SurfaceCase {
  std::string file, name, title, source;
  //! `[surface] shape` or the `[[surface.shapes]]`, in order: surface k's points start in
  //! chamber k.
  std::vector<NamedSurface<D>> surfaces;
  double smoothing_length = 0.0;    //!< h of every initial point
  double spacing = 0.0;             //!< minimum distance of the initial cloud
  SourceLocation spacing_where;     //!< surface.smoothing_length in the input
  PointSample<D> sample;            //!< the initial cloud, every surface's points in turn
  std::vector<int> sample_surface;  //!< which surface each point of `sample` lies on
  SurfaceSettings settings;
  std::array<PointFormula, D> velocity;
  std::unique_ptr<SurfacePde<D>> pde;  //!< null: the cloud only moves
  OutputSettings output;
  //! history.csv columns `mean_<name>`: the mean over the points of a formula.
  std::vector<std::pair<std::string, PointFormula>> monitors;

  std::vector<const SurfaceShape<D>*> shapes() const {
    std::vector<const SurfaceShape<D>*> out;
    for (const auto& s : surfaces)
      if (s.shape) out.push_back(s.shape.get());
    return out;
  }
};

//! Whether the case describes a surface problem (a `[surface]` table).
bool is_surface_case(const CaseSource& source);
//! 2 (curves) or 3 (surfaces), from the shape's kind.
int surface_case_dimension(const CaseSource& source);
//! Type and check every key, then sample the initial cloud. Throws InputError listing every
//! problem found.
template <int D>
SurfaceCase<D> read_surface_case(const CaseSource& source);
//! The simulation the case describes (the initial cloud and its geometry).
template <int D>
std::unique_ptr<SurfaceSimulation<D>> build_surface_simulation(SurfaceCase<D>& c);

}  // namespace pellicle
