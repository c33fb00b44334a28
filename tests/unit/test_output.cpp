// Output files: history columns, complete VTK snapshots (decoded back), the ParaView series,
// summary.json, and no temporary files left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pellicle/io/output.hpp"
#include "pellicle/io/run.hpp"
#include "pellicle/io/vtk_writer.hpp"
#include "pellicle/mpm/grid_projection.hpp"
#include "support/case_text.hpp"
#include "support/vtk_files.hpp"

namespace pellicle {
namespace {

namespace fs = std::filesystem;
using test::base64_decode;
using test::decoded_array;
using test::read_all;

const std::string kCase = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.25
[solver]
end_time = 0.01
dt = 0.001
gravity = [0.0, -9.81]
[output]
history_interval = 0.005
snapshot_interval = 0.005
grid_snapshots = true
[[material]]
name = "m"
model = "linear-elastic"
density = 10.0
youngs_modulus = 1000.0
[[body]]
name = "block-A"
material = "m"
points_per_cell = 1
velocity = [0.5, 0.0]
region = { shape = "box", lower = [0.25, 0.25], upper = [0.75, 0.5] }
)";

TEST(Output, ARunThatReachesMaxStepsStopsAndSaysSo) {
  // 10 steps to the end; at most 4. (pellicle run refuses this before it starts; a time
  // step that collapses during a run is caught here.)
  const fs::path dir = fs::temp_directory_path() / "pellicle_test_max_steps";
  fs::remove_all(dir);
  const auto source = case_source_from_text(kCase, "<test>", {"solver.max_steps=4"});
  Case<2> c = read_case<2>(*source);
  c.output.directory = dir.string();
  auto simulation = build_simulation<2>(c);
  OutputWriter<2> output(c.output, *simulation);
  try {
    run_simulation(*simulation, output, nullptr, RunControl{});
    ADD_FAILURE() << "the run did not stop";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.max_steps = 4 reached before end_time"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.context().step, 4);
  }
  EXPECT_NE(read_all(dir / "summary.json").find("\"status\": \"failed: "), std::string::npos);
}

TEST(Output, RunWritesCompleteFiles) {
  const fs::path dir = fs::temp_directory_path() / "pellicle_test_output";
  fs::remove_all(dir);
  const auto source = case_source_from_text(kCase, "<test>");
  Case<2> c = read_case<2>(*source);
  c.output.directory = dir.string();
  auto simulation = build_simulation<2>(c);
  OutputWriter<2> output(c.output, *simulation);
  RunControl control;
  control.case_hash = "abc";
  run_simulation(*simulation, output, nullptr, control);

  // history.csv: header with per-body columns, rows at t = 0, 0.005, 0.01.
  std::istringstream history(read_all(dir / "history.csv"));
  std::string header, row;
  std::getline(history, header);
  EXPECT_EQ(header,
            "time,step,dt,kinetic,strain,internal,gravitational,total,momentum_x,momentum_y,"
            "block-A.com_x,block-A.com_y,block-A.vel_x,block-A.vel_y");
  int rows = 0;
  while (std::getline(history, row)) ++rows;
  EXPECT_EQ(rows, 3);

  // Snapshots and series.
  EXPECT_TRUE(fs::exists(dir / "points_000002.vtu"));
  EXPECT_TRUE(fs::exists(dir / "grid_000002.vti"));
  const std::string pvd = read_all(dir / "points.pvd");
  EXPECT_NE(pvd.find("<DataSet timestep=\"0.01"), std::string::npos) << pvd;
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().extension(), ".part") << entry.path();

  // The positions array decodes to the points' coordinates.
  const std::string vtu = read_all(dir / "points_000002.vtu");
  const auto begin = vtu.find('>', vtu.find("Name=\"position\"")) + 1;
  const auto end = vtu.find("</DataArray>", begin);
  const auto bytes = base64_decode(vtu.substr(begin, end - begin));
  std::uint64_t count;
  std::memcpy(&count, bytes.data(), 8);
  const auto& p = simulation->points();
  ASSERT_EQ(count, 3 * 8 * static_cast<std::uint64_t>(p.size()));
  for (long i = 0; i < p.size(); ++i) {
    double xyz[3];
    std::memcpy(xyz, bytes.data() + 8 + 24 * i, 24);
    EXPECT_EQ(xyz[0], p.position[i].x());
    EXPECT_EQ(xyz[1], p.position[i].y());
    EXPECT_EQ(xyz[2], 0.0);
  }

  const std::string summary = read_all(dir / "summary.json");
  EXPECT_NE(summary.find("\"status\": \"completed\""), std::string::npos);
  EXPECT_NE(summary.find("\"steps\": 10"), std::string::npos) << summary;
  fs::remove_all(dir);
}

TEST(Output, GridSnapshotHoldsProjectedStresses) {
  // Gas at p = (γ − 1) ρ e = 100 filling the grid; the t = 0 grid snapshot.
  const std::string text = R"(
[grid]
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cell = 0.25
boundary = { x_min = "slip", x_max = "slip", y_min = "slip", y_max = "slip" }
[solver]
end_time = 0.002
dt = 0.001
[output]
snapshot_interval = 0.001
grid_snapshots = true
[[material]]
name = "gas"
model = "gas"
gamma = 1.4
density = 1.0
[[body]]
name = "gas"
material = "gas"
internal_energy = 250.0
region = { shape = "box", lower = [0.0, 0.0], upper = [1.0, 1.0] }
)";
  const fs::path dir = fs::temp_directory_path() / "pellicle_test_grid_output";
  fs::remove_all(dir);
  const auto source = case_source_from_text(text, "<test>");
  Case<2> c = read_case<2>(*source);
  c.output.directory = dir.string();
  auto simulation = build_simulation<2>(c);
  OutputWriter<2> output(c.output, *simulation);
  RunControl control;
  run_simulation(*simulation, output, nullptr, control);
  ASSERT_TRUE(fs::exists(dir / "grid_000002.vti"));

  const std::string vti = read_all(dir / "grid_000000.vti");
  const int nx = 4 + 1 + 2 * Grid<2>::kGhost;  // nodes per axis, ghosts included
  ASSERT_NE(vti.find("WholeExtent=\"0 8 0 8 0 0\""), std::string::npos) << vti.substr(0, 400);
  const std::size_t nodes = nx * nx;
  int k = 0;
  const auto mass = decoded_array<double>(vti, "mass", k);
  EXPECT_EQ(k, 1);
  EXPECT_EQ(mass.size(), nodes);
  const auto pressure = decoded_array<double>(vti, "pressure", k);
  EXPECT_EQ(k, 1);
  ASSERT_EQ(pressure.size(), nodes);
  const auto stress = decoded_array<double>(vti, "stress", k);
  EXPECT_EQ(k, 6);
  ASSERT_EQ(stress.size(), 6 * nodes);
  const auto membrane = decoded_array<double>(vti, "membrane_stress", k);
  EXPECT_EQ(k, 6);
  ASSERT_EQ(membrane.size(), 6 * nodes);
  // The written arrays are the projection's, node for node: give the points a pressure
  // that varies with x and y (so a transposed or shifted array would show), project, write.
  auto& points = simulation->points();
  for (long i = 0; i < points.size(); ++i) {
    const double q = 100.0 + 10.0 * points.position[i].x() + 3.0 * points.position[i].y();
    points.stress[i] << -q, -q, -q, 0.5 * q;
  }
  GridProjection<2> projection;
  const NodeStresses<2>& f = projection.project(*simulation);
  write_grid_vti<2>((dir / "varying.vti").string(), simulation->grid(), f);
  const std::string varying = read_all(dir / "varying.vti");
  const auto p2 = decoded_array<double>(varying, "pressure", k);
  const auto s2 = decoded_array<double>(varying, "stress", k);
  ASSERT_EQ(p2.size(), nodes);
  ASSERT_EQ(s2.size(), 6 * nodes);
  for (std::size_t n = 0; n < nodes; ++n) {  // x fastest, as VTK orders image data
    EXPECT_EQ(p2[n], f.pressure[n]) << "node " << n;
    EXPECT_EQ(s2[6 * n + 0], f.stress[n][0]) << "node " << n;  // xx
    EXPECT_EQ(s2[6 * n + 3], f.stress[n][3]) << "node " << n;  // xy
  }
  EXPECT_GT(*std::max_element(p2.begin(), p2.end()), 110.0);  // the field varies
  for (double v : membrane) EXPECT_EQ(v, 0.0);

  // Particle snapshots flag the fluid points.
  const auto fluid = decoded_array<std::uint8_t>(read_all(dir / "points_000000.vtu"), "fluid", k);
  EXPECT_EQ(k, 1);
  EXPECT_EQ(static_cast<long>(fluid.size()), simulation->points().size());
  for (auto flag : fluid) EXPECT_EQ(flag, 1);
  fs::remove_all(dir);
}

TEST(Output, CaseHashIsStable) {
  EXPECT_EQ(hash_text(""), "cbf29ce484222325");  // FNV-1a offset basis
  EXPECT_NE(hash_text("a"), hash_text("b"));
}

}  // namespace
}  // namespace pellicle
