//! The validation problems: one file each, one line here.
#include <cstdio>

#include "pellicle/validation/problem.hpp"

namespace pellicle::validation {

const std::vector<Problem>& problems() {
  static const std::vector<Problem> list = {
      {"bar-vibration", "Free–free elastic bar, axial period (2D and 3D, every kernel)",
       "thesis ch. 3, ch. 8", &bar_vibration},
      {"cylinder-radial", "Solid cylinder, radial modes (axisymmetric)", "thesis §6.3 formulation",
       &cylinder_radial_vibration},
      {"two-disks", "Two elastic disks collide and rebound", "Sulsky, Chen & Schreyer 1994",
       &two_disks},
      {"two-bars-stick", "Two-bar impact, single velocity field: the bars stick",
       "IJNME 1999 §4.1 Fig. 18; thesis A.1.2", &two_bars_stick},
      {"two-bars-release", "Two-bar impact with contact-release: the bars part, three grids",
       "IJNME 1999 §4.2 Fig. 20; thesis A.1.5", &two_bars_release},
      {"disks-wire", "Two disks pinch a wire and part from it (contact-release)",
       "IJNME 1999 §4.3 Figs 21-22", &disks_wire},
      {"ball-and-net", "Ball and net: the ball leaves the net with contact-release",
       "thesis §5.9, A.1.6", &ball_and_net},
      {"offset-disks", "Offset disks pinch a wire: spin while pinching and after release",
       "IJNME 1999 §4.4 Fig. 23", &offset_disks},
      {"spring-mass", "Spring–mass oscillator; stability at 1.6 and 1.7 Δt_crit",
       "IJNME 1999 §3.1.1; thesis §5.5", &spring_mass},
      {"stability", "Critical time step of a kicked bar, points at cell centres and beside nodes",
       "thesis §8.4-8.5, Fig 91, deck A.4.11", &stability},
      {"string-slack", "String with slack, one-way law: free fall, tension, free flight",
       "IJNME 1999 §3.2; thesis §5.6", &string_slack},
      {"pendulum", "Pendulum: string with end mass against bar elements, four grids",
       "IJNME 1999 §3.1.2; thesis §5.7", &pendulum},
      {"drum", "Pre-tensioned circular drum (3D membrane): fundamental frequency",
       "thesis §5.8; classical membrane theory", &drum},
      {"sphere-breathing", "Spherical membrane, breathing mode (3D curved membrane)",
       "thesis §5.8; membrane-shell theory", &sphere_breathing},
      {"normals-accuracy", "Normals of whole closed curves and surfaces, every estimator",
       "Sulsky & York 2000; thesis ch. 7", &normals_accuracy},
      {"normal-methods-fsi",
       "Every frame estimator on gas-filled membranes: expanding cylinder and dog-bone",
       "thesis §7.5, §7.7; Sulsky & York 2000 §8 ex. 2", &normal_methods_fsi},
      {"sod", "Sod's shock tube against the exact Riemann solution, 100/200/400 cells",
       "thesis §4.1, deck A.4.1", &sod},
      {"strong-shock", "Strong shock tube (pressure ratio 100) against the exact Riemann solution",
       "held-out Riemann problem; thesis §4.1 set-up", &strong_shock},
      {"gas-expansion", "Quarter cylinder of gas expanding into vacuum: energy, edge speed",
       "thesis §4.2, deck A.4.2", &gas_expansion},
      {"piston-container",
       "Piston on a spring over a liquid column: period (two masses, two liquids)",
       "thesis §6.1, deck A.4.10", &piston_container},
      {"dogbone", "Gas-filled dog-bone membrane expands to a circle: Tables 5-6, four grids",
       "thesis §6.2, Tables 4-6, deck A.4.7", &dogbone},
      {"airbag", "Airbag impact: bag inflated with a tether, then Cyl-200 and Cyl-500 probes",
       "thesis §6.3, Tables 7-8, decks A.4.8-A.4.9", &airbag},
      {"friction-block", "Block sliding on an incline: Coulomb friction, μ = 0, 0.3, 0.7",
       "Bardenhagen, Brackbill & Sulsky 2000; analytic", &friction_block},
      {"surface-movement",
       "Moving point clouds: rotating quarter sphere, deforming hemisphere with management",
       "Suchde & Kuhnert §3.7.1-3.7.2", &surface_movement},
      {"surface-point-addition",
       "Curvature-corrected addition of points on a sphere and a torus (Table 1, Figure 11)",
       "Suchde & Kuhnert §3.4.1, §3.7.4", &surface_point_addition},
      {"curvature-flow",
       "Geometric flows: a sphere under mean-curvature flow, an ellipsoid under averaged flow",
       "Suchde & Kuhnert §4.2.3", &surface_curvature_flow},
      {"joining-spheres", "Two spheres meeting: non-penetration, delete and merge contact",
       "Suchde & Kuhnert §3.6, §3.7.3", &surface_joining_spheres},
      {"dumbbell-pinch", "Dumbbell under mean-curvature flow: the neck pinches into two surfaces",
       "Suchde & Kuhnert §3.6, §4.2.3", &surface_dumbbell_pinch},
      {"torus-genus", "Torus under averaged flow: the hole closes, genus 1 to 0",
       "Suchde & Kuhnert §3.6, §4.2.3", &surface_torus_genus},
      {"wave-collapse",
       "Wave on a creature collapsing onto itself: through folds and self-contact (Fig. 16)",
       "Suchde & Kuhnert §3.6, §4.2.4", &surface_wave_collapse},
      {"surface-cdr-sphere", "Convection-diffusion-reaction on an expanding sphere: Tables 2 and 3",
       "Suchde & Kuhnert §4.2.1", &surface_cdr_sphere},
      {"surface-wave-sphere", "Wave equation on an expanding sphere: Table 4",
       "Suchde & Kuhnert §4.2.4", &surface_wave_sphere},
      {"surface-half-pipe",
       "Diffusion on a deforming half pipe: conservation of the integral of phi (Figure 13)",
       "Suchde & Kuhnert §4.2.2", &surface_half_pipe},
      {"laplace-spectrum", "Laplace-Beltrami eigenvalues of point clouds: sphere and torus",
       "Suchde & Kuhnert §4.1 operators; analytic and separated references", &laplace_spectrum},
  };
  return list;
}

const Problem* find_problem(const std::string& name) {
  for (const auto& p : problems())
    if (p.name == name) return &p;
  return nullptr;
}

std::string Check::describe() const {
  char text[512];
  std::snprintf(text, sizeof text, "%s = %.6g%s%s (reference %.6g, accepted [%.6g, %.6g]) %s",
                quantity.c_str(), measured, unit.empty() ? "" : " ", unit.c_str(), reference, lower,
                upper, passed() ? "ok" : "FAILED");
  return text;
}

}  // namespace pellicle::validation
