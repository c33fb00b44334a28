#include "pellicle/io/vtk_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "pellicle/io/atomic_file.hpp"
#include "pellicle/io/vtk_arrays.hpp"

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

//! Declared columns as ParaView arrays: vectors as xyz, symmetric tensors in ParaView's
//! order, matrices row by row.
template <int D>
void write_declared_columns(std::string& out, const Particles<D>& p) {
  const std::size_t n = p.position.size();
  for (int c = 0; c < p.columns.count(); ++c) {
    if (!p.columns.spec(c).snapshot) continue;
    const double* data = p.columns.data(c);
    const int k = p.columns.components(c);
    const std::string& name = p.columns.spec(c).name;
    switch (p.columns.shape(c)) {
      case ColumnShape::scalar:
        data_array(out, "Float64", name, 1, std::vector<double>(data, data + n));
        break;
      case ColumnShape::vector:
        data_array(out, "Float64", name, 3,
                   as_xyz<D>(std::vector<Vec<D>>(reinterpret_cast<const Vec<D>*>(data),
                                                 reinterpret_cast<const Vec<D>*>(data) + n)));
        break;
      case ColumnShape::symmetric:
        data_array(
            out, "Float64", name, 6,
            as_paraview_tensor<D>(std::vector<Sym<D>>(reinterpret_cast<const Sym<D>*>(data),
                                                      reinterpret_cast<const Sym<D>*>(data) + n)));
        break;
      case ColumnShape::matrix:
        data_array(out, "Float64", name, k, std::vector<double>(data, data + n * k));
        break;
    }
  }
}

//! What materials compute for snapshots (membrane strain and stress in the local axes), over
//! every point, zero where a body's material does not compute it.
template <int D>
void write_material_fields(std::string& out, const Simulation<D>& s) {
  const Particles<D>& p = s.points();
  std::vector<std::pair<SnapshotField, std::vector<double>>> fields;
  for (const auto& b : p.bodies) {
    const auto& material = s.material(b.material);
    const auto offered = material.snapshot_fields();
    for (std::size_t f = 0; f < offered.size(); ++f) {
      auto it = std::find_if(fields.begin(), fields.end(),
                             [&](const auto& e) { return e.first.name == offered[f].name; });
      if (it == fields.end()) {
        fields.emplace_back(offered[f], std::vector<double>(offered[f].components * p.size()));
        it = fields.end() - 1;
      }
      material.snapshot_values(static_cast<int>(f), p, b.begin, b.end,
                               it->second.data() + offered[f].components * b.begin);
    }
  }
  for (const auto& [field, values] : fields)
    data_array(out, "Float64", field.name, field.components, values);
}

}  // namespace

namespace {

//! Bytes per point of the arrays a points snapshot holds (before base64), and of those the
//! material fields, which are computed all at once.
template <int D>
std::pair<std::size_t, std::size_t> snapshot_bytes_per_point(const Simulation<D>& simulation) {
  const Particles<D>& p = simulation.points();
  // Fixed arrays: position, velocity (3 each), mass, volume, density, stress (6), pressure,
  // von Mises as doubles; body, connectivity, offsets (int32); fluid, types (bytes).
  std::size_t per_point = 8 * (3 + 3 + 3 + 6 + 2) + 3 * 4 + 2;
  for (int c = 0; c < p.columns.count(); ++c) {
    if (!p.columns.spec(c).snapshot) continue;
    const ColumnShape shape = p.columns.shape(c);
    per_point += 8 * (shape == ColumnShape::vector      ? 3
                      : shape == ColumnShape::symmetric ? 6
                                                        : p.columns.components(c));
  }
  std::size_t material_fields = 0;
  std::vector<std::string> seen;
  for (const auto& b : p.bodies)
    for (const auto& f : simulation.material(b.material).snapshot_fields())
      if (std::find(seen.begin(), seen.end(), f.name) == seen.end())
        seen.push_back(f.name), material_fields += 8 * f.components;
  return {per_point + material_fields, material_fields};
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
  std::vector<std::uint8_t> fluid(n, 0);
  for (const auto& b : p.bodies)
    if (simulation.material(b.material).is_fluid())
      std::fill(fluid.begin() + b.begin, fluid.begin() + b.end, std::uint8_t{1});

  // The whole text is held until it is written: reserved at its size (base64: 4 characters
  // per 3 bytes, and each array's tags), so it is never copied to grow.
  std::string out;
  out.reserve(n * (snapshot_bytes_per_point(simulation).first * 4 / 3 + 4) + 16384);
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
  data_array(out, "Float64", "pressure", 1, pressure);
  data_array(out, "Float64", "von_mises", 1, von_mises);
  data_array(out, "Int32", "body", 1, body);
  data_array(out, "UInt8", "fluid", 1, fluid);
  write_declared_columns(out, p);
  write_material_fields(out, simulation);
  out += "</PointData>\n<Cells>\n";
  data_array(out, "Int32", "connectivity", 1, connectivity);
  data_array(out, "Int32", "offsets", 1, offsets);
  data_array(out, "UInt8", "types", 1, types);
  out += "</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

template <int D>
void write_grid_vti(const std::string& path, const Grid<D>& grid, const NodeStresses<D>& stresses) {
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
  data_array(out, "Float64", "pressure", 1, stresses.pressure);
  data_array(out, "Float64", "stress", 6, as_paraview_tensor<D>(stresses.stress));
  data_array(out, "Float64", "membrane_stress", 6, as_paraview_tensor<D>(stresses.membrane_stress));
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

template <int D>
std::size_t points_vtu_peak_bytes(const Simulation<D>& simulation) {
  const auto [arrays, material_fields] = snapshot_bytes_per_point(simulation);
  // The text, the material fields, and the largest array being encoded (48 bytes a point).
  return static_cast<std::size_t>(simulation.points().size()) *
         (arrays * 4 / 3 + material_fields + 48);
}

template std::size_t points_vtu_peak_bytes<2>(const Simulation<2>&);
template std::size_t points_vtu_peak_bytes<3>(const Simulation<3>&);
template void write_points_vtu<2>(const std::string&, const Simulation<2>&);
template void write_points_vtu<3>(const std::string&, const Simulation<3>&);
template void write_grid_vti<2>(const std::string&, const Grid<2>&, const NodeStresses<2>&);
template void write_grid_vti<3>(const std::string&, const Grid<3>&, const NodeStresses<3>&);

}  // namespace pellicle
