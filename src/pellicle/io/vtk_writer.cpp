#include "pellicle/io/vtk_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <type_traits>

#include "pellicle/io/atomic_file.hpp"
#include "pellicle/io/vtk_arrays.hpp"

namespace pellicle {
namespace {

//! The six ParaView components (xx, yy, zz, xy, yz, xz) of a symmetric tensor.
template <int D>
void paraview_tensor(const Sym<D>& s, double* out) {
  const Mat3 m = to_mat3<D>(s);
  const double c[6] = {m(0, 0), m(1, 1), m(2, 2), m(0, 1), m(1, 2), m(0, 2)};
  std::copy(c, c + 6, out);
}

//! Symmetric tensors in ParaView's 6-component order.
template <int D>
std::vector<double> as_paraview_tensor(const std::vector<Sym<D>>& s) {
  std::vector<double> out(6 * s.size());
  for (std::size_t i = 0; i < s.size(); ++i) paraview_tensor<D>(s[i], out.data() + 6 * i);
  return out;
}

//! A column of values of type T per point as a Float64 array: vectors as xyz, symmetric
//! tensors in ParaView's order, scalars and matrices (row by row) as they are.
template <int D, class T>
void stream_point_array(AtomicFileWriter& file, const std::string& name, const T* values,
                        std::size_t n) {
  if constexpr (std::is_same_v<T, double>) {
    stream_data_array<double>(file, "Float64", name, 1, n,
                              [&](std::size_t first, std::size_t last, double* out) {
                                std::copy(values + first, values + last, out);
                              });
  } else if constexpr (std::is_same_v<T, Vec<D>>) {
    stream_data_array<double>(file, "Float64", name, 3, n,
                              [&](std::size_t first, std::size_t last, double* out) {
                                for (std::size_t i = first; i < last; ++i, out += 3) {
                                  out[2] = 0.0;
                                  for (int d = 0; d < D; ++d) out[d] = values[i][d];
                                }
                              });
  } else {
    static_assert(std::is_same_v<T, Sym<D>>);
    stream_data_array<double>(file, "Float64", name, 6, n,
                              [&](std::size_t first, std::size_t last, double* out) {
                                for (std::size_t i = first; i < last; ++i, out += 6)
                                  paraview_tensor<D>(values[i], out);
                              });
  }
}

//! Declared columns as ParaView arrays.
template <int D>
void write_declared_columns(AtomicFileWriter& file, const Particles<D>& p) {
  const std::size_t n = p.position.size();
  for (int c = 0; c < p.columns.count(); ++c) {
    if (!p.columns.spec(c).snapshot) continue;
    const double* data = p.columns.data(c);
    const std::string& name = p.columns.spec(c).name;
    switch (p.columns.shape(c)) {
      case ColumnShape::scalar:
        stream_point_array<D>(file, name, data, n);
        break;
      case ColumnShape::vector:
        stream_point_array<D>(file, name, reinterpret_cast<const Vec<D>*>(data), n);
        break;
      case ColumnShape::symmetric:
        stream_point_array<D>(file, name, reinterpret_cast<const Sym<D>*>(data), n);
        break;
      case ColumnShape::matrix: {
        const int k = p.columns.components(c);
        stream_data_array<double>(file, "Float64", name, k, n,
                                  [&](std::size_t first, std::size_t last, double* out) {
                                    std::copy(data + first * k, data + last * k, out);
                                  });
        break;
      }
    }
  }
}

//! Snapshot fields the bodies' materials compute, each once, in the order of first offer.
template <int D>
std::vector<SnapshotField> material_fields(const Simulation<D>& s) {
  std::vector<SnapshotField> fields;
  for (const auto& b : s.points().bodies)
    for (const auto& f : s.material(b.material).snapshot_fields())
      if (std::none_of(fields.begin(), fields.end(),
                       [&](const SnapshotField& e) { return e.name == f.name; }))
        fields.push_back(f);
  return fields;
}

//! What materials compute for snapshots (membrane strain and stress in the local axes), over
//! every point, zero where a body's material does not compute it.
template <int D>
void write_material_fields(AtomicFileWriter& file, const Simulation<D>& s) {
  const Particles<D>& p = s.points();
  for (const auto& field : material_fields(s)) {
    stream_data_array<double>(
        file, "Float64", field.name, field.components, p.position.size(),
        [&](std::size_t first, std::size_t last, double* out) {
          std::fill(out, out + (last - first) * field.components, 0.0);
          for (const auto& b : p.bodies) {
            const long begin = std::max<long>(b.begin, first), end = std::min<long>(b.end, last);
            if (begin >= end) continue;
            const auto& material = s.material(b.material);
            const auto offered = material.snapshot_fields();
            for (std::size_t f = 0; f < offered.size(); ++f)
              if (offered[f].name == field.name)
                material.snapshot_values(static_cast<int>(f), p, begin, end,
                                         out + field.components * (begin - first));
          }
        });
  }
}

}  // namespace

template <int D>
void write_points_vtu(const std::string& path, const Simulation<D>& simulation) {
  const Particles<D>& p = simulation.points();
  const std::size_t n = p.position.size();
  std::vector<std::uint8_t> fluid_body(p.bodies.size(), 0);
  for (std::size_t b = 0; b < p.bodies.size(); ++b)
    fluid_body[b] = simulation.material(p.bodies[b].material).is_fluid() ? 1 : 0;

  // Written array by array, a few thousand points at a time: the file's text is never held.
  AtomicFileWriter file(path);
  std::string head =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<UnstructuredGrid>\n<FieldData>\n";
  data_array(head, "Float64", "TIME", 1, std::vector<double>{simulation.time()});
  head += "</FieldData>\n<Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfCells=\"" +
          std::to_string(n) + "\">\n<Points>\n";
  file.write(head);
  stream_point_array<D>(file, "position", p.position.data(), n);
  file.write("</Points>\n<PointData Scalars=\"von_mises\" Vectors=\"velocity\">\n");
  stream_point_array<D>(file, "velocity", p.velocity.data(), n);
  stream_point_array<D>(file, "mass", p.mass.data(), n);
  stream_point_array<D>(file, "volume", p.volume.data(), n);
  stream_point_array<D>(file, "density", p.density.data(), n);
  stream_point_array<D>(file, "stress", p.stress.data(), n);
  stream_data_array<double>(file, "Float64", "pressure", 1, n,
                            [&](std::size_t first, std::size_t last, double* out) {
                              for (std::size_t i = first; i < last; ++i)
                                *out++ = -to_mat3<D>(p.stress[i]).trace() / 3.0;
                            });
  stream_data_array<double>(file, "Float64", "von_mises", 1, n,
                            [&](std::size_t first, std::size_t last, double* out) {
                              for (std::size_t i = first; i < last; ++i) {
                                const Mat3 s = to_mat3<D>(p.stress[i]);
                                const Mat3 dev = s + (-s.trace() / 3.0) * Mat3::Identity();
                                *out++ = std::sqrt(1.5 * (dev.array() * dev.array()).sum());
                              }
                            });
  stream_data_array<std::int32_t>(file, "Int32", "body", 1, n,
                                  [&](std::size_t first, std::size_t last, std::int32_t* out) {
                                    std::copy(p.body.begin() + first, p.body.begin() + last, out);
                                  });
  stream_data_array<std::uint8_t>(file, "UInt8", "fluid", 1, n,
                                  [&](std::size_t first, std::size_t last, std::uint8_t* out) {
                                    for (std::size_t i = first; i < last; ++i)
                                      *out++ = fluid_body[p.body[i]];
                                  });
  write_declared_columns(file, p);
  write_material_fields(file, simulation);
  file.write("</PointData>\n<Cells>\n");
  stream_data_array<std::int32_t>(file, "Int32", "connectivity", 1, n,
                                  [](std::size_t first, std::size_t last, std::int32_t* out) {
                                    for (std::size_t i = first; i < last; ++i)
                                      *out++ = static_cast<std::int32_t>(i);
                                  });
  stream_data_array<std::int32_t>(file, "Int32", "offsets", 1, n,
                                  [](std::size_t first, std::size_t last, std::int32_t* out) {
                                    for (std::size_t i = first; i < last; ++i)
                                      *out++ = static_cast<std::int32_t>(i + 1);
                                  });
  stream_data_array<std::uint8_t>(file, "UInt8", "types", 1, n,  // VTK_VERTEX
                                  [](std::size_t first, std::size_t last, std::uint8_t* out) {
                                    std::fill(out, out + (last - first), std::uint8_t{1});
                                  });
  file.write("</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  file.commit();
}

template <int D>
void write_points_pvtu(const std::string& path, const Simulation<D>& simulation,
                       const std::vector<std::string>& pieces) {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<PUnstructuredGrid GhostLevel=\"0\">\n";
  auto array = [&out](const char* type, const std::string& name, int components) {
    out += "<PDataArray type=\"" + std::string(type) + "\" Name=\"" + name +
           "\" NumberOfComponents=\"" + std::to_string(components) + "\"/>\n";
  };
  out += "<PPoints>\n";
  array("Float64", "position", 3);
  out += "</PPoints>\n<PPointData Scalars=\"von_mises\" Vectors=\"velocity\">\n";
  // In write_points_vtu's order.
  array("Float64", "velocity", 3);
  for (const char* name : {"mass", "volume", "density"}) array("Float64", name, 1);
  array("Float64", "stress", 6);
  array("Float64", "pressure", 1);
  array("Float64", "von_mises", 1);
  array("Int32", "body", 1);
  array("UInt8", "fluid", 1);
  const PointColumns& columns = simulation.points().columns;
  for (int c = 0; c < columns.count(); ++c) {
    if (!columns.spec(c).snapshot) continue;
    const ColumnShape shape = columns.shape(c);
    array("Float64", columns.spec(c).name,
          shape == ColumnShape::vector      ? 3
          : shape == ColumnShape::symmetric ? 6
                                            : columns.components(c));
  }
  for (const auto& field : material_fields(simulation))
    array("Float64", field.name, field.components);
  out += "</PPointData>\n<PCells>\n";
  array("Int32", "connectivity", 1);
  array("Int32", "offsets", 1);
  array("UInt8", "types", 1);
  out += "</PCells>\n";
  for (const auto& piece : pieces) out += "<Piece Source=\"" + piece + "\"/>\n";
  out += "</PUnstructuredGrid>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

namespace {

//! The VTK extent "i0 i1 j0 j1 k0 k1" of nodes first to last.
template <int D>
std::string extent(const IVec<D>& first, const IVec<D>& last) {
  std::ostringstream e;
  for (int d = 0; d < 3; ++d)
    e << (d ? " " : "") << (d < D ? first[d] : 0) << ' ' << (d < D ? last[d] : 0);
  return e.str();
}

//! The image's placement: grid index 0 at the origin, one cell per index.
template <int D>
std::string origin_and_spacing(const Grid<D>& grid) {
  std::ostringstream out;
  out.precision(17);
  const Vec<D> origin = grid.node_position(IVec<D>::Zero());
  out << "Origin=\"" << origin[0] << ' ' << origin[1] << ' ' << (D == 3 ? origin[D - 1] : 0.0)
      << "\" Spacing=\"" << grid.cell() << ' ' << grid.cell() << ' ' << grid.cell() << '"';
  return out.str();
}

//! Values of the stored nodes first to last, axis 0 fastest.
template <int D, class T>
std::vector<T> node_box(const Grid<D>& grid, const std::vector<T>& values, const IVec<D>& first,
                        const IVec<D>& last) {
  std::vector<T> out;
  IVec<D> c = first;
  while (true) {
    out.push_back(values[grid.flatten(c)]);
    int d = 0;
    while (d < D && ++c[d] > last[d]) c[d] = first[d], ++d;
    if (d == D) break;
  }
  return out;
}

}  // namespace

template <int D>
void write_grid_vti(const std::string& path, const Grid<D>& grid, const NodeStresses<D>& stresses,
                    const IVec<D>& first, const IVec<D>& last) {
  const std::string e = extent<D>(first, last);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<ImageData WholeExtent=\"" +
      e + "\" " + origin_and_spacing(grid) + ">\n<Piece Extent=\"" + e +
      "\">\n<PointData Scalars=\"mass\" Vectors=\"velocity\">\n";
  auto box = [&](const auto& values) { return node_box<D>(grid, values, first, last); };
  data_array(out, "Float64", "mass", 1, box(grid.mass));
  data_array(out, "Float64", "velocity", 3, as_xyz<D>(box(grid.velocity)));
  data_array(out, "Float64", "pressure", 1, box(stresses.pressure));
  data_array(out, "Float64", "stress", 6, as_paraview_tensor<D>(box(stresses.stress)));
  data_array(out, "Float64", "membrane_stress", 6,
             as_paraview_tensor<D>(box(stresses.membrane_stress)));
  out += "</PointData>\n<CellData>\n</CellData>\n</Piece>\n</ImageData>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

template <int D>
void write_grid_pvti(const std::string& path, const Grid<D>& grid,
                     const std::vector<std::string>& pieces, const std::vector<IVec<D>>& first,
                     const std::vector<IVec<D>>& last) {
  IVec<D> lowest = first.front(), highest = last.front();
  for (std::size_t r = 1; r < pieces.size(); ++r)
    lowest = lowest.cwiseMin(first[r]), highest = highest.cwiseMax(last[r]);
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"PImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n<PImageData WholeExtent=\"" +
      extent<D>(lowest, highest) + "\" GhostLevel=\"0\" " + origin_and_spacing(grid) +
      ">\n<PPointData Scalars=\"mass\" Vectors=\"velocity\">\n";
  for (const auto& [name, components] : {std::pair<const char*, int>{"mass", 1},
                                         {"velocity", 3},
                                         {"pressure", 1},
                                         {"stress", 6},
                                         {"membrane_stress", 6}})
    out += "<PDataArray type=\"Float64\" Name=\"" + std::string(name) + "\" NumberOfComponents=\"" +
           std::to_string(components) + "\"/>\n";
  out += "</PPointData>\n";
  for (std::size_t r = 0; r < pieces.size(); ++r)
    out +=
        "<Piece Extent=\"" + extent<D>(first[r], last[r]) + "\" Source=\"" + pieces[r] + "\"/>\n";
  out += "</PImageData>\n</VTKFile>\n";
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
template void write_points_pvtu<2>(const std::string&, const Simulation<2>&,
                                   const std::vector<std::string>&);
template void write_points_pvtu<3>(const std::string&, const Simulation<3>&,
                                   const std::vector<std::string>&);
template void write_grid_vti<2>(const std::string&, const Grid<2>&, const NodeStresses<2>&,
                                const IVec<2>&, const IVec<2>&);
template void write_grid_vti<3>(const std::string&, const Grid<3>&, const NodeStresses<3>&,
                                const IVec<3>&, const IVec<3>&);
template void write_grid_pvti<2>(const std::string&, const Grid<2>&,
                                 const std::vector<std::string>&, const std::vector<IVec<2>>&,
                                 const std::vector<IVec<2>>&);
template void write_grid_pvti<3>(const std::string&, const Grid<3>&,
                                 const std::vector<std::string>&, const std::vector<IVec<3>>&,
                                 const std::vector<IVec<3>>&);

}  // namespace pellicle
