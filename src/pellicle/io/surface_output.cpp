#include "pellicle/io/surface_output.hpp"

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "pellicle/io/atomic_file.hpp"
#include "pellicle/io/json_text.hpp"
#include "pellicle/io/output_directory.hpp"
#include "pellicle/io/vtk_arrays.hpp"
#include "pellicle/surface/components.hpp"
#include "pellicle/surface/errors.hpp"
#include "pellicle/surface/quadrature.hpp"

namespace pellicle {

template <int D>
void write_surface_vtp(const std::string& path, const SurfaceSimulation<D>& s) {
  const PointCloud<D>& c = s.cloud();
  const std::size_t n = c.size();
  std::vector<std::int32_t> connectivity(n), offsets(n);
  std::vector<double> normals(3 * n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int32_t>(i);
    offsets[i] = static_cast<std::int32_t>(i + 1);
    for (int d = 0; d < D; ++d) normals[3 * i + d] = c.frame[i](d, D - 1);
  }
  std::vector<std::uint8_t> boundary(c.boundary.begin(), c.boundary.end());
  std::string out;
  out.reserve(n * 160 + 4096);
  out +=
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" "
      "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PolyData>\n<FieldData>\n";
  data_array(out, "Float64", "TIME", 1, std::vector<double>{s.time()});
  out += "</FieldData>\n<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfVerts=\"" +
         std::to_string(n) + "\">\n<Points>\n";
  data_array(out, "Float64", "position", 3, as_xyz<D>(c.position));
  out += "</Points>\n<PointData Normals=\"normal\" Vectors=\"velocity\">\n";
  data_array(out, "Float64", "normal", 3, normals);
  data_array(out, "Float64", "velocity", 3, as_xyz<D>(c.velocity));
  data_array(out, "Float64", "smoothing_length", 1, c.smoothing_length);
  data_array(out, "UInt8", "boundary", 1, boundary);
  data_array(out, "Int32", "chamber", 1,
             std::vector<std::int32_t>(c.chamber.begin(), c.chamber.end()));
  data_array(out, "Float64", "curvature", 1, s.curvature());
  for (std::size_t f = 0; f < c.field_names().size(); ++f)
    data_array(out, "Float64", c.field_names()[f], 1, c.field(static_cast<int>(f)));
  if (const SurfacePde<D>* pde = s.pde(); pde && pde->exact()) {
    std::vector<double> exact(n), error(n);
    for (std::size_t i = 0; i < n; ++i) {
      exact[i] = (*pde->exact())(s.values_at(i, s.time()));
      error[i] = c.field(pde->unknown())[i] - exact[i];
    }
    data_array(out, "Float64", "exact", 1, exact);
    data_array(out, "Float64", "error", 1, error);
  }
  out += "</PointData>\n<Verts>\n";
  data_array(out, "Int32", "connectivity", 1, connectivity);
  data_array(out, "Int32", "offsets", 1, offsets);
  out += "</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

template <int D>
SurfaceOutputWriter<D>::SurfaceOutputWriter(
    const OutputSettings& settings, const SurfaceSimulation<D>& s,
    std::vector<std::pair<std::string, PointFormula>> monitors)
    : settings_(settings),
      monitors_(std::move(monitors)),
      series_(settings.directory + "/surface.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(settings_.directory, ec);
  if (ec) throw std::runtime_error("cannot create " + settings_.directory + ": " + ec.message());
  history_.open(settings_.directory + "/history.csv", std::ios::trunc);
  if (!history_) throw std::runtime_error("cannot write " + settings_.directory + "/history.csv");
  history_ << "time,step,points,added,merged,removed,solver_iterations,solver_residual,area,"
              "enclosed_volume,parts,chambers,contact_points,contact_removed";
  if (s.pde()) history_ << ",total_phi";
  if (s.pde() && s.pde()->exact()) history_ << ",error_l2,error_max";
  for (const auto& [name, formula] : monitors_) history_ << ",mean_" << name;
  history_ << '\n' << std::setprecision(12);
  write_row(s);
  write_snapshot(s);
}

template <int D>
void SurfaceOutputWriter<D>::write_row(const SurfaceSimulation<D>& s) {
  const auto& m = s.management_total();
  history_ << s.time() << ',' << s.step_count() << ',' << s.cloud().size() << ',' << m.added << ','
           << m.merged << ',' << m.removed << ',' << s.last_solve().iterations << ','
           << s.last_solve().residual;
  const std::vector<double>* phi = s.pde() ? &s.cloud().field(s.pde()->unknown()) : nullptr;
  const SurfaceIntegrals totals = integrate(s.cloud(), s.neighbours(), phi, areas_);
  history_ << ',' << totals.area << ',' << totals.enclosed << ','
           << connected_parts(s.neighbours(), &s.external_neighbours()) << ','
           << s.cloud().chamber_count() << ',' << s.last_contact().in_contact << ','
           << s.contact_total().removed + s.debris_removed();
  if (phi) history_ << ',' << totals.integral;
  if (s.pde() && s.pde()->exact()) {
    const SolutionErrors e = solution_errors(s);
    history_ << ',' << e.relative_l2 << ',' << e.max;
  }
  for (const auto& [name, formula] : monitors_) history_ << ',' << mean_over_points(s, formula);
  history_ << '\n';
  history_.flush();
  if (!history_) throw std::runtime_error("cannot write " + settings_.directory + "/history.csv");
  last_row_ = s.step_count();
  next_row_ = s.time() + settings_.history_interval;
}

template <int D>
void SurfaceOutputWriter<D>::write_snapshot(const SurfaceSimulation<D>& s) {
  char name[32];
  std::snprintf(name, sizeof name, "surface_%06d.vtp", snapshots_);
  write_surface_vtp<D>(settings_.directory + "/" + name, s);
  series_.add(s.time(), name);
  ++snapshots_;
  last_snapshot_ = s.step_count();
  next_snapshot_ = settings_.snapshot_interval > 0.0 ? s.time() + settings_.snapshot_interval
                                                     : std::numeric_limits<double>::infinity();
}

template <int D>
void SurfaceOutputWriter<D>::after_step(const SurfaceSimulation<D>& s) {
  const double t = s.time() + 1e-9 * s.settings().dt;  // rows on the intended times
  if (t >= next_row_) write_row(s);
  if (t >= next_snapshot_) write_snapshot(s);
}

template <int D>
void SurfaceOutputWriter<D>::finish(const SurfaceSimulation<D>& s, const std::string& status,
                                    const std::string& case_hash, double wall_seconds) {
  if (last_row_ != s.step_count()) write_row(s);
  if (last_snapshot_ != s.step_count()) write_snapshot(s);
  const SolutionErrors e = solution_errors(s);
  const auto& m = s.management_total();
  std::ostringstream j;
  j << "{\n";
  j << "  \"version\": " << json_string(PELLICLE_VERSION) << ",\n";
  j << "  \"status\": " << json_string(status) << ",\n";
  j << "  \"case_hash\": " << json_string(case_hash) << ",\n";
  j << "  \"time\": " << json_number(s.time()) << ",\n";
  j << "  \"steps\": " << s.step_count() << ",\n";
  j << "  \"points\": " << s.cloud().size() << ",\n";
  j << "  \"points_added\": " << m.added << ",\n";
  j << "  \"points_merged\": " << m.merged << ",\n";
  j << "  \"points_removed\": " << m.removed << ",\n";
  j << "  \"error_l2\": " << json_number(e.relative_l2) << ",\n";
  j << "  \"error_max\": " << json_number(e.max) << ",\n";
  j << "  \"wall_seconds\": " << json_number(wall_seconds) << "\n}\n";
  write_file_atomically(settings_.directory + "/summary.json", j.str());
  mark_output_directory(settings_.directory, status);
}

template void write_surface_vtp<2>(const std::string&, const SurfaceSimulation<2>&);
template void write_surface_vtp<3>(const std::string&, const SurfaceSimulation<3>&);
template class SurfaceOutputWriter<2>;
template class SurfaceOutputWriter<3>;

}  // namespace pellicle
