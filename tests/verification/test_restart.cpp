// Checkpoint and restart: a run continued from a checkpoint reproduces the uninterrupted run
// bit for bit (membrane frames, a gas's internal energy, contact-release's node states all
// carried), and restarts the case cannot honour are refused with the key named.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "pellicle/io/case_source.hpp"
#include "pellicle/io/checkpoint.hpp"
#include "pellicle/io/restart.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

namespace fs = std::filesystem;

// The disks pinching a wire (two solids, a membrane, contact-release with kept node states),
// in plane strain so that a gas may join them.
std::string disks_and_wire() {
  std::string text = testing::case_file("disks_wire.toml");
  const std::string stress = "kinematics = \"plane-stress\"";
  return text.replace(text.find(stress), stress.size(), "kinematics = \"plane-strain\"");
}

// The same with a gas column beside them.
std::string restart_case() {
  return disks_and_wire() + R"(
[[material]]
name = "air"
model = "gas"
density = 1.0
gamma = 1.4
artificial_viscosity = {linear = 0.2, quadratic = 1.0}

[[body]]
name = "gas"
material = "air"
region = {shape = "box", lower = [8.5, 1.0], upper = [9.5, 3.0]}
internal_energy = 2.5
)";
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("pellicle_restart_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

template <int D>
void expect_identical(const Particles<D>& a, const Particles<D>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (long p = 0; p < a.size(); ++p) {
    ASSERT_EQ(a.position[p], b.position[p]) << "point " << p;
    ASSERT_EQ(a.velocity[p], b.velocity[p]) << "point " << p;
    ASSERT_EQ(a.stress[p], b.stress[p]) << "point " << p;
    ASSERT_EQ(a.density[p], b.density[p]) << "point " << p;
  }
  ASSERT_EQ(a.columns.count(), b.columns.count());
  for (int c = 0; c < a.columns.count(); ++c) {
    const long n = a.size() * a.columns.components(c);
    for (long i = 0; i < n; ++i)
      ASSERT_EQ(a.columns.data(c)[i], b.columns.data(c)[i]) << a.columns.spec(c).name;
  }
}

TEST(Restart, ContinuesBitForBitWithMembraneGasAndContact) {
  const fs::path dir = scratch("bits");
  const auto source = case_source_from_text(restart_case(), "<restart case>");
  const std::string checkpoint = (dir / "checkpoint.h5").string();

  Case<2> ca = read_case<2>(*source);
  auto a = build_simulation<2>(ca);
  a->run(300);  // the disks reach the wire by then: contact and release at shared nodes
  write_checkpoint(checkpoint, *a, checkpoint_header_for(*source));
  std::vector<HookState> saved;
  for (const auto& hook : a->hooks()) saved.push_back(hook->save_state());
  a->run(600);

  Case<2> cb = read_case<2>(*source);
  auto b = build_simulation<2>(cb);
  EXPECT_TRUE(restore_checkpoint<2>(checkpoint, *b).empty());
  EXPECT_EQ(b->step_count(), 300);
  // Contact-release's kept node states (criterion 9.9) come back as they were saved.
  ASSERT_EQ(b->hooks().size(), saved.size());
  for (std::size_t h = 0; h < saved.size(); ++h) EXPECT_EQ(b->hooks()[h]->save_state(), saved[h]);
  EXPECT_FALSE(saved.back().empty());
  b->run(600);

  EXPECT_EQ(a->time(), b->time());
  EXPECT_GT(a->contact_forces()->at(0).norm(), 0.0);  // contact acted: the test means something
  expect_identical(a->points(), b->points());
}

TEST(Restart, RefusesWhatItCannotHonour) {
  const fs::path dir = scratch("refuse");
  const auto source = case_source_from_text(restart_case(), "<restart case>");
  Case<2> c = read_case<2>(*source);
  auto s = build_simulation<2>(c);
  s->run(2);
  const std::string checkpoint = (dir / "checkpoint.h5").string();
  write_checkpoint(checkpoint, *s, checkpoint_header_for(*source));
  const CheckpointHeader saved = read_checkpoint_header(checkpoint);
  EXPECT_EQ(saved.step, 2);

  auto refusal = [&](const std::vector<std::string>& overrides) -> std::string {
    const auto changed = case_source_from_text(restart_case(), "<changed>", overrides);
    try {
      check_restart(saved, checkpoint, *changed);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  // Restart-safe: time stepping, output, contact, faces.
  EXPECT_EQ(
      refusal({"solver.end_time=9.0", "solver.cfl=0.3", "output.snapshot_interval=1.0",
               "contact.model=friction", "contact.coefficient=0.2", "grid.boundary.x_min=free"}),
      "");
  EXPECT_NE(refusal({"grid.cell=0.125"}).find("grid.cell"), std::string::npos);
  EXPECT_NE(refusal({"solver.kernel=linear"}).find("solver.kernel"), std::string::npos);
  EXPECT_NE(refusal({"body[0].velocity=[2.0, 0.0]"}).find("body 'disk-I'"), std::string::npos);
  // Re-parameterised: what acts on a kept body from now on, and its material's parameters
  // (the airbag's gas made inviscid, its tether cut); not the state it starts from, nor the
  // material's model.
  EXPECT_EQ(refusal({"material[0].youngs_modulus=2e4", "body[0].external_force=[0.0, -1.0]",
                     "body[2].cut_at=0.5", "body[2].membrane.frames=pca"}),
            "");
  EXPECT_NE(refusal({"material[0].model=gas"}).find("material 'disk'"), std::string::npos);
  EXPECT_NE(refusal({"body[2].membrane.thickness=0.5"}).find("body 'wire'"), std::string::npos);

  CheckpointHeader other = saved;
  other.version = "0.0.1";
  EXPECT_THROW(check_restart(other, checkpoint, *source), InputError);
  other = saved;
  other.dimension = 3;
  EXPECT_THROW(check_restart(other, checkpoint, *source), InputError);

  const fs::path text = dir / "not_a_checkpoint.h5";
  std::ofstream(text) << "time,step\n";
  EXPECT_THROW(read_checkpoint_header(text.string()), InputError);
  EXPECT_THROW(read_checkpoint_header((dir / "missing.h5").string()), InputError);
}

TEST(Restart, TheVelocityUpdateMayChangeIfTheCheckpointHoldsWhatItNeeds) {
  // An APIC run (the airbag's inflation) may continue with FLIP (its impact); a FLIP run
  // cannot continue with APIC: its checkpoint has no affine velocities.
  const fs::path dir = scratch("velocity_update");
  auto run_and_save = [&](const std::string& update) {
    const auto source = case_source_from_text(restart_case(), "<" + update + ">",
                                              {"solver.velocity_update=" + update});
    Case<2> c = read_case<2>(*source);
    auto s = build_simulation<2>(c);
    s->run(5);
    const std::string checkpoint = (dir / (update + ".h5")).string();
    write_checkpoint(checkpoint, *s, checkpoint_header_for(*source));
    return checkpoint;
  };
  auto restart = [&](const std::string& checkpoint, const std::string& update) -> std::string {
    const auto source =
        case_source_from_text(restart_case(), "<restart>", {"solver.velocity_update=" + update});
    try {
      check_restart(read_checkpoint_header(checkpoint), checkpoint, *source);
      Case<2> c = read_case<2>(*source);
      auto s = build_simulation<2>(c);
      restore_checkpoint<2>(checkpoint, *s);
      s->run(10);
      EXPECT_EQ(s->step_count(), 10);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const std::string apic = run_and_save("apic"), flip = run_and_save("flip");
  EXPECT_EQ(restart(apic, "flip"), "");
  EXPECT_EQ(restart(flip, "pic"), "");
  EXPECT_NE(restart(flip, "apic").find("the checkpoint has no 'columns/affine'"), std::string::npos)
      << restart(flip, "apic");
}

TEST(Restart, AddedAndRemovedBodies) {
  const fs::path dir = scratch("bodies");
  const auto source = case_source_from_text(restart_case(), "<restart case>");
  Case<2> c = read_case<2>(*source);
  auto s = build_simulation<2>(c);
  s->run(3);
  const std::string checkpoint = (dir / "checkpoint.h5").string();
  write_checkpoint(checkpoint, *s, checkpoint_header_for(*source));

  // A probe body added (the airbag's impactor): it starts from its case state.
  const std::string added = restart_case() + R"(
[[body]]
name = "probe"
material = "disk"
region = {shape = "box", lower = [4.0, 8.5], upper = [5.0, 9.5]}
velocity = [0.0, -1.0]
)";
  const auto with_probe = case_source_from_text(added, "<added>");
  EXPECT_NO_THROW(check_restart(read_checkpoint_header(checkpoint), checkpoint, *with_probe));
  Case<2> ca = read_case<2>(*with_probe);
  auto a = build_simulation<2>(ca);
  EXPECT_EQ(restore_checkpoint<2>(checkpoint, *a), std::vector<std::string>{"probe"});
  EXPECT_EQ(a->step_count(), 3);
  const auto& probe = a->points().bodies.back();
  EXPECT_EQ(a->points().velocity[probe.begin], Vec2(0.0, -1.0));
  EXPECT_EQ(a->points().position[0], s->points().position[0]);  // kept bodies carried
  a->run(5);

  // The gas and its material removed (the airbag's tether): the rest continues.
  const auto without_gas = case_source_from_text(disks_and_wire(), "<less>");
  EXPECT_NO_THROW(check_restart(read_checkpoint_header(checkpoint), checkpoint, *without_gas));
  Case<2> cr = read_case<2>(*without_gas);
  auto r = build_simulation<2>(cr);
  EXPECT_TRUE(restore_checkpoint<2>(checkpoint, *r).empty());
  EXPECT_EQ(r->points().position.back(), s->points().position[r->points().size() - 1]);
  r->run(5);
}

}  // namespace
}  // namespace pellicle
