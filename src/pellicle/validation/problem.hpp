#pragma once
//! Validation problems: the seeds' examples and analytic solutions, each measured against its
//! reference with a stated tolerance. `pellicle validate` runs them (fast or full
//! resolution) and writes a report with plots; tests/verification runs the fast variants.

#include <string>
#include <vector>

namespace pellicle::validation {

enum class Resolution { fast, full };

//! One measured quantity and its admissible range.
struct Check {
  std::string quantity;  //!< what was measured, e.g. "period error, quadratic-bspline"
  double measured = 0.0;
  double reference = 0.0;           //!< the analytic or published value
  double lower = 0.0, upper = 0.0;  //!< passes when lower ≤ measured ≤ upper
  std::string unit;
  bool passed() const { return measured >= lower && measured <= upper; }
  //! "period error = 0.68 % (reference 0, accepted [-1, 1] %)"
  std::string describe() const;
};

//! A table for plotting: the first column is the abscissa.
struct Series {
  std::string name;  //!< file stem
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

struct Outcome {
  std::vector<Check> checks;
  std::vector<Series> series;
  std::string table;  //!< optional markdown written into the report after the checks
};

struct Problem {
  std::string name;  //!< short id: "bar-vibration"
  std::string title;
  std::string source;  //!< seed section
  Outcome (*run)(Resolution);
};

//! Every validation problem (registry.cpp).
const std::vector<Problem>& problems();
//! Problem by name; nullptr if unknown.
const Problem* find_problem(const std::string& name);

// The problems (one file each).
Outcome bar_vibration(Resolution resolution);
Outcome cylinder_radial_vibration(Resolution resolution);
Outcome two_disks(Resolution resolution);
Outcome two_bars_stick(Resolution resolution);
Outcome pendulum(Resolution resolution);
Outcome spring_mass(Resolution resolution);
Outcome stability(Resolution resolution);
Outcome string_slack(Resolution resolution);
Outcome drum(Resolution resolution);
Outcome sphere_breathing(Resolution resolution);
Outcome normals_accuracy(Resolution resolution);
Outcome sod(Resolution resolution);
Outcome strong_shock(Resolution resolution);
Outcome gas_expansion(Resolution resolution);
Outcome piston_container(Resolution resolution);
Outcome friction_block(Resolution resolution);
Outcome two_bars_release(Resolution resolution);
Outcome disks_wire(Resolution resolution);
Outcome offset_disks(Resolution resolution);
Outcome ball_and_net(Resolution resolution);
Outcome dogbone(Resolution resolution);
Outcome airbag(Resolution resolution);
Outcome surface_cdr_sphere(Resolution resolution);
Outcome surface_curvature_flow(Resolution resolution);
Outcome surface_joining_spheres(Resolution resolution);
Outcome surface_dumbbell_pinch(Resolution resolution);
Outcome surface_torus_genus(Resolution resolution);
Outcome surface_wave_collapse(Resolution resolution);
Outcome surface_wave_sphere(Resolution resolution);
Outcome surface_half_pipe(Resolution resolution);
Outcome laplace_spectrum(Resolution resolution);
Outcome surface_movement(Resolution resolution);
Outcome surface_point_addition(Resolution resolution);
Outcome normal_methods_fsi(Resolution resolution);

}  // namespace pellicle::validation
