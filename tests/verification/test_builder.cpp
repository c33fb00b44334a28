// The C++ builder: the two-disk problem assembled without a case file runs exactly as the
// same case read from TOML (the reader calls the builder), and the builder refuses what
// cannot run.
#include <gtest/gtest.h>

#include "pellicle/mpm/builder.hpp"
#include "pellicle/mpm/contact/contact_model.hpp"
#include "pellicle/mpm/materials/linear_elastic.hpp"
#include "support/case_text.hpp"

namespace pellicle {
namespace {

constexpr double kCell = 0.05;

SimulationBuilder<2> two_disks(UpdateScheme scheme = UpdateScheme::musl) {
  const FaceConditions<2> free{FaceCondition::free, FaceCondition::free, FaceCondition::free,
                               FaceCondition::free};
  SimulationBuilder<2> b(Vec2(0.0, 0.0), Vec2(1.0, 1.0), kCell, free);
  SimulationSettings settings;
  settings.scheme = scheme;
  settings.kinematics = Kinematics::plane_strain;
  settings.cfl_fraction = 0.4;
  settings.end_time = 3.0;
  TransferOptions transfer;
  transfer.update = VelocityUpdate::apic;
  b.settings(settings).kernel("quadratic-bspline", transfer);
  const int elastic =
      b.material(std::make_unique<LinearElastic<2>>(Kinematics::plane_strain, 1000.0, 1000.0, 0.3));
  for (int k = 0; k < 2; ++k) {
    BodySetup<2> disk;
    disk.name = k == 0 ? "lower-disk" : "upper-disk";
    disk.material = elastic;
    disk.velocity = k == 0 ? Vec2(0.1, 0.1) : Vec2(-0.1, -0.1);
    disk.region = make_ball<2>(k == 0 ? Vec2(0.2, 0.2) : Vec2(0.8, 0.8), 0.2);
    b.body(std::move(disk));
  }
  return b;
}

TEST(Builder, TwoDisksWithoutACaseFileRunAsTheCaseDoes) {
  auto built = two_disks().build();
  auto read =
      testing::simulation_from_text<2>(testing::case_file("two_disks.toml"), {"grid.cell=0.05"});
  ASSERT_EQ(built->points().size(), read->points().size());
  built->run(200);
  read->run(200);
  EXPECT_EQ(built->time(), read->time());
  for (long p = 0; p < built->points().size(); ++p) {
    ASSERT_EQ(built->points().position[p], read->points().position[p]) << p;
    ASSERT_EQ(built->points().stress[p], read->points().stress[p]) << p;
  }
  // The disks met: momentum still zero (each disk's is ±0.1 m/s × its mass).
  EXPECT_LT(built->state().momentum.norm(), 1e-12);
  EXPECT_GT(built->state().strain, 0.0);
}

TEST(Builder, RefusesWhatCannotRun) {
  auto usf = two_disks(UpdateScheme::usf);
  // USF updates the stress from mapped velocities no contact rule corrected.
  struct AlwaysContact final : ContactModel<2> {
    std::string describe() const override { return "test"; }
    void resolve(GridFields<2>&, const Particles<2>&, double, GridPass) override {}
  };
  usf.contact(std::make_unique<AlwaysContact>());
  EXPECT_THROW(usf.build(), SetupError);

  auto empty = two_disks();
  BodySetup<2> outside;
  outside.name = "outside";
  outside.region = make_ball<2>(Vec2(5.0, 5.0), 0.2);
  empty.body(std::move(outside));
  try {
    empty.build();
    ADD_FAILURE() << "a body without points was accepted";
  } catch (const BuildError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_EQ(e.problems()[0].body, 2);
    EXPECT_EQ(e.problems()[0].key, "region");
  }

  auto linear_apic = two_disks();
  TransferOptions apic;
  apic.update = VelocityUpdate::apic;
  linear_apic.kernel("linear", apic);
  EXPECT_THROW(linear_apic.build(), BuildError);
}

}  // namespace
}  // namespace pellicle
