#include "pellicle/io/vtk_writer.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "pellicle/io/atomic_file.hpp"
#include "pellicle/io/vtk_arrays.hpp"
#include "pellicle/mpm/materials/membrane.hpp"

namespace pellicle {
namespace {

//! Symmetric tensors in ParaView's 6-component order: xx, yy, zz, xy, yz, xz.
template <int D>
std::vector<double> as_paraview_tensor(const std::vector<Sym<D>>& s) {
  std::vector<double> out(6 * s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Mat3 m = to_mat3<D>(s[i]);
    const double c[6] = {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2)};
    std::copy(c, c + 6, out.begin() + 6 * i);
  }
  return out;
}

template <int D>
bool has_membranes(const Simulation<D>& s) {
  for (const auto& b : s.points().bodies)
    if (b.frames) return true;
  return false;
}

template <int D>
bool has_fluids(const Simulation<D>& s) {
  for (const auto& b : s.points().bodies)
    if (s.material(b.material).is_fluid()) return true;
  return false;
}

//! Membrane points: frame, and strain and stress in the local axes (11 tangent, 22 second
//! in-surface direction, 12 in-surface shear); zero for other points.
template <int D>
void write_membrane_fields(std::string& out, const Simulation<D>& s) {
  const Particles<D>& p = s.points();
  const std::size_t n = p.position.size();
  std::vector<double> strain(3 * n, 0.0), stress(3 * n, 0.0);
  for (const auto& b : p.bodies) {
    if (!b.frames) continue;
    for (long i = b.begin; i < b.end; ++i) {
      const Mat3 Q = membrane_axes(p.tangent[i], p.normal[i]);
      const Mat3 e = Q * to_mat3<D>(p.strain[i]) * Q.transpose();
      const Mat3 t = Q * to_mat3<D>(p.stress[i]) * Q.transpose();
      const double le[3] = {e(0, 0), e(1, 1), e(0, 1)}, lt[3] = {t(0, 0), t(1, 1), t(0, 1)};
      std::copy(le, le + 3, strain.begin() + 3 * i);
      std::copy(lt, lt + 3, stress.begin() + 3 * i);
    }
  }
  data_array(out, "Float64", "normal", 3, as_xyz<D>(p.normal));
  data_array(out, "Float64", "tangent", 3, as_xyz<D>(p.tangent));
  data_array(out, "Float64", "membrane_strain", 3, strain);
  data_array(out, "Float64", "membrane_stress", 3, stress);
}

}  // namespace

template <int D>
void write_points_vtu(const std::string& path, const Simulation<D>& simulation) {
  const Particles<D>& p = simulation.points();
  const std::size_t n = p.position.size();
  std::vector<double> pressure(n), von_mises(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Mat3 s = to_mat3<D>(p.stress[i]);
    pressure[i] = -s.trace() / 3.0;
    const Mat3 dev = s + pressure[i] * Mat3::Identity();
    von_mises[i] = std::sqrt(1.5 * (dev.array() * dev.array()).sum());
  }
  std::vector<std::int32_t> connectivity(n), offsets(n);
  std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
  for (std::size_t i = 0; i < n; ++i) {
    connectivity[i] = static_cast<std::int32_t>(i);
    offsets[i] = static_cast<std::int32_t>(i + 1);
  }
  std::vector<std::int32_t> body(p.body.begin(), p.body.end());

  std::string out;
  out.reserve(n * 200 + 4096);
  out += "<?xml version=\"1.0\"?>\n";
  out +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<UnstructuredGrid>\n";
  out += "<FieldData>\n";
  data_array(out, "Float64", "TIME", 1, std::vector<double>{simulation.time()});
  out += "</FieldData>\n";
  out += "<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" +
         std::to_string(n) + "\">\n<Points>\n";
  data_array(out, "Float64", "position", 3, as_xyz<D>(p.position));
  out += "</Points>\n<PointData Scalars=\"von_mises\" Vectors=\"velocity\">\n";
  data_array(out, "Float64", "velocity", 3, as_xyz<D>(p.velocity));
  data_array(out, "Float64", "mass", 1, p.mass);
  data_array(out, "Float64", "volume", 1, p.volume);
  data_array(out, "Float64", "density", 1, p.density);
  data_array(out, "Float64", "stress", 6, as_paraview_tensor<D>(p.stress));
  data_array(out, "Float64", "strain", 6, as_paraview_tensor<D>(p.strain));
  data_array(out, "Float64", "pressure", 1, pressure);
  data_array(out, "Float64", "von_mises", 1, von_mises);
  data_array(out, "Int32", "body", 1, body);
  if (has_membranes(simulation)) write_membrane_fields(out, simulation);
  if (has_fluids(simulation)) data_array(out, "Float64", "internal_energy", 1, p.energy);
  out += "</PointData>\n<Cells>\n";
  data_array(out, "Int32", "connectivity", 1, connectivity);
  data_array(out, "Int32", "offsets", 1, offsets);
  data_array(out, "UInt8", "types", 1, types);
  out += "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

template <int D>
void write_grid_vti(const std::string& path, const Grid<D>& grid) {
  const IVec<D> n = grid.nodes();
  const Vec<D> origin = grid.node_position(IVec<D>::Zero());
  std::ostringstream head;
  head.precision(17);
  head << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
          "header_type=\"UInt64\">\n";
  head << "<ImageData WholeExtent=\"0 " << n[0] - 1 << " 0 " << n[1] - 1 << " 0 "
       << (D == 3 ? n[D - 1] - 1 : 0) << "\" Origin=\"" << origin[0] << ' ' << origin[1] << ' '
       << (D == 3 ? origin[D - 1] : 0.0) << "\" Spacing=\"" << grid.cell() << ' ' << grid.cell()
       << ' ' << grid.cell() << "\">\n";
  head << "<Piece Extent=\"0 " << n[0] - 1 << " 0 " << n[1] - 1 << " 0 "
       << (D == 3 ? n[D - 1] - 1 : 0) << "\">\n<PointData Scalars=\"mass\" Vectors=\"velocity\">\n";
  std::string out = head.str();
  data_array(out, "Float64", "mass", 1, grid.mass);
  data_array(out, "Float64", "velocity", 3, as_xyz<D>(grid.velocity));
  out += "</PointData>\n<CellData>\n</CellData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

void PvdCollection::add(double time, const std::string& file) {
  entries_.emplace_back(time, file);
  std::ostringstream out;
  out.precision(17);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" "
         "byte_order=\"LittleEndian\">\n<Collection>\n";
  for (const auto& [t, f] : entries_)
    out << "  <DataSet timestep=\"" << t << "\" file=\"" << f << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  write_file_atomically(path_, out.str());
}

template void write_points_vtu<2>(const std::string&, const Simulation<2>&);
template void write_points_vtu<3>(const std::string&, const Simulation<3>&);
template void write_grid_vti<2>(const std::string&, const Grid<2>&);
template void write_grid_vti<3>(const std::string&, const Grid<3>&);

}  // namespace pellicle
