// Point migration (dist/migration.hpp): random points of random bodies leave for random ranks
// (their own included, which moves them within the arrays), many times over. Every point must
// arrive once, whole (all its columns), in its own body, with every body contiguous.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "pellicle/dist/migration.hpp"
#include "world.hpp"

namespace pellicle {
namespace {

//! Per body: points, Σ id, Σ id² over every rank (the id is the point's mass; its velocity,
//! stress and declared column hold copies of it).
std::vector<double> body_totals(const Particles<2>& p) {
  std::vector<double> t;
  for (const auto& b : p.bodies) {
    double ids = 0.0, squares = 0.0;
    for (long i = b.begin; i < b.end; ++i) ids += p.mass[i], squares += p.mass[i] * p.mass[i];
    t.insert(t.end(), {static_cast<double>(b.count()), ids, squares});
  }
  world->sum_in_rank_order(t);
  return t;
}

TEST(Migration, EveryPointArrivesOnceWithItsColumnsInItsBody) {
  const int me = world->rank();
  Particles<2> p;
  const std::vector<long> sizes = {5, 0, 40, 1, 17};
  long id = 1000 * (me + 1);
  for (std::size_t b = 0; b < sizes.size(); ++b) {
    p.bodies.push_back({});
    p.bodies.back().begin = p.size();
    p.bodies.back().end = p.size();
    for (long i = 0; i < sizes[b] + me; ++i, ++id)
      p.add(Vec<2>::Constant(0.0), Vec<2>::Constant(id), static_cast<double>(id), 1.0);
  }
  const auto tag = p.declare<Vec<2>>({"tag", "1"});
  for (long i = 0; i < p.size(); ++i) {
    p[tag][i] = Vec<2>(p.mass[i], -p.mass[i]);
    p.stress[i] = Sym<2>::Constant(p.mass[i]);
  }
  const std::vector<double> before = body_totals(p);

  // Every other round the ranks are a chain: each has the ranks beside it as neighbours,
  // and the points go to them (counts between neighbours only), except every fourth such
  // round, when they go anywhere (every rank falls back to the all-to-all).
  std::vector<int> chain, near = {me};
  for (int r : {me - 1, me + 1})
    if (r >= 0 && r < world->size()) chain.push_back(r), near.push_back(r);
  std::mt19937 random(12345u + me);
  for (int round = 0; round < 60; ++round) {
    std::vector<LeavingPoint> leaving;
    const double share = (round % 4) / 3.0;  // none, a third, two thirds, all
    const bool neighbours = round % 2 == 1, anywhere = round % 8 == 7;
    for (long i = 0; i < p.size(); ++i)
      if (std::uniform_real_distribution<double>(0.0, 1.0)(random) < share) {
        const int rank = neighbours && !anywhere ? near[random() % near.size()]
                                                 : static_cast<int>(random() % world->size());
        leaving.push_back({i, rank});
      }
    migrate_points(*world, leaving, p, neighbours ? &chain : nullptr);
    long expected_begin = 0;
    for (std::size_t b = 0; b < p.bodies.size(); ++b) {
      EXPECT_EQ(p.bodies[b].begin, expected_begin);
      expected_begin = p.bodies[b].end;
      for (long i = p.bodies[b].begin; i < p.bodies[b].end; ++i) {
        EXPECT_EQ(p.body[i], static_cast<int>(b));
        EXPECT_EQ(p.velocity[i], Vec<2>::Constant(p.mass[i]));
        EXPECT_EQ(p[tag][i], Vec<2>(p.mass[i], -p.mass[i]));
        EXPECT_EQ(p.stress[i], Sym<2>::Constant(p.mass[i]));
        EXPECT_EQ(p.volume[i], p.mass[i]);
      }
    }
    EXPECT_EQ(expected_begin, p.size());
    EXPECT_EQ(body_totals(p), before) << "round " << round;
  }
}

}  // namespace
}  // namespace pellicle
