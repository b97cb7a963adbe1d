#include "strahler/base/random.h"
#include "strahler/landscape/evolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace strahler::landscape {
namespace {

/// A grid with every node fixed at `wall` metres except those the caller frees.
EvolutionInput walledGrid(int columns, int rows, double wall) {
  EvolutionInput in;
  in.tree = LatticeGrid<double>::filled(columns, rows, wall);
  in.roles = LatticeGrid<NodeRole>::filled(columns, rows, NodeRole::kBaseLevel);
  in.erodibility = LatticeGrid<float>::filled(columns, rows, 1.0f);
  in.diffusivity = LatticeGrid<float>::filled(columns, rows, 1.0f);
  return in;
}

TEST(Evolution, OneStepOfStreamPowerMatchesTheImplicitFormula) {
  // One free node at 100 m whose only lower neighbour is an outlet at 0 m (the rest are 500 m
  // walls): its receiver is the outlet, its area one cell, and Braun & Willett's implicit step
  // with the restoring uplift gives h1 = (h0 + u·tree + F·0) / (1 + u + F), F = K A^m / Δx.
  EvolutionInput in = walledGrid(3, 3, 500.0);
  in.tree.values[in.tree.at(1, 1)] = 100.0;
  in.roles.values[in.roles.at(1, 1)] = NodeRole::kFree;
  in.tree.values[in.tree.at(1, 0)] = 0.0;
  EvolutionParams p;
  p.spacing = 60.0;
  p.steps = 1;
  p.incision = 0.3;
  p.restoring = 0.05;
  p.diffusivity = 0.0;
  const EvolutionResult out = evolveLandscape(in, p);
  const double f = 0.3 * std::pow(60.0 * 60.0, 0.45) / 60.0;
  const double expected = (100.0 + 0.05 * 100.0 + f * 0.0) / (1.0 + 0.05 + f);
  EXPECT_NEAR(out.heights.values[out.heights.at(1, 1)], expected, 1e-9);
  EXPECT_FLOAT_EQ(out.area.values[out.area.at(1, 1)], 3600.0f);
  EXPECT_EQ(out.heights.values[out.heights.at(1, 0)], 0.0); // fixed nodes do not move
}

TEST(Evolution, HillslopeTransportMatchesTheNonlinearFlux) {
  // A free spike of h metres among four fixed neighbours at 0 (diagonals at 0 too): without
  // incision or uplift, one step moves it by the four edge fluxes κ h / (1 − (S/Sc)²) with
  // S = h / Δx, each coefficient capped at 0.12 for stability.
  for (const double h : {3.0, 30.0}) {
    EvolutionInput in = walledGrid(3, 3, 0.0);
    in.tree.values[in.tree.at(1, 1)] = h;
    in.roles.values[in.roles.at(1, 1)] = NodeRole::kFree;
    EvolutionParams p;
    p.spacing = 60.0;
    p.steps = 1;
    p.incision = 0.0;
    p.restoring = 0.0;
    p.diffusivity = 0.02;
    p.criticalSlope = 1.0;
    // A peak: no incision (K = 0) or uplift moves it, the transport lowers it, and the final
    // filling leaves it (it drains to its fixed neighbours).
    const EvolutionResult out = evolveLandscape(in, p);
    const double s = h / 60.0;
    const double coefficient = std::min(0.02 / (1.0 - std::min(s * s, 0.75)), 0.12);
    EXPECT_NEAR(out.heights.values[out.heights.at(1, 1)], h - 4.0 * coefficient * h, 1e-9)
        << "h = " << h;
  }
}

/// A random 64 × 48 land with a base-level border, a pinned line and varied fields.
EvolutionInput randomLand(std::uint64_t seed) {
  EvolutionInput in = walledGrid(64, 48, 0.0);
  base::Rng rng(seed);
  for (int r = 1; r + 1 < 48; ++r)
    for (int c = 1; c + 1 < 64; ++c) {
      const std::size_t i = in.tree.at(c, r);
      in.roles.values[i] = c == 32 ? NodeRole::kPinned : NodeRole::kFree;
      in.tree.values[i] = 5.0 * std::min(std::min(c, 63 - c), std::min(r, 47 - r)) +
                          (c == 32 ? 0.0 : rng.uniform(0.0, 20.0));
      in.erodibility.values[i] = static_cast<float>(rng.uniform(0.5, 1.5));
      in.diffusivity.values[i] = static_cast<float>(rng.uniform(0.5, 1.5));
    }
  return in;
}

TEST(Evolution, SameBitsOnAnyThreadCount) {
  const EvolutionInput in = randomLand(3);
  EvolutionParams p;
  p.steps = 12;
  p.seed = 99;
  p.threads = 1;
  const EvolutionResult one = evolveLandscape(in, p);
  p.threads = 2;
  const EvolutionResult two = evolveLandscape(in, p);
  p.threads = 5;
  const EvolutionResult five = evolveLandscape(in, p);
  ASSERT_EQ(one.heights.values.size(), two.heights.values.size());
  EXPECT_EQ(std::memcmp(one.heights.values.data(), two.heights.values.data(),
                        one.heights.values.size() * sizeof(double)),
            0);
  EXPECT_EQ(std::memcmp(one.heights.values.data(), five.heights.values.data(),
                        one.heights.values.size() * sizeof(double)),
            0);
  EXPECT_EQ(one.area.values, two.area.values);
}

TEST(Evolution, ErodedLandDrainsAndFixedNodesKeepTheirHeights) {
  const EvolutionInput in = randomLand(5);
  EvolutionParams p;
  p.steps = 20;
  p.seed = 1;
  const EvolutionResult out = evolveLandscape(in, p);
  double lowered = 0.0;
  int free = 0;
  for (int r = 0; r < 48; ++r)
    for (int c = 0; c < 64; ++c) {
      const std::size_t i = out.heights.at(c, r);
      if (in.roles.values[i] != NodeRole::kFree) {
        ASSERT_EQ(out.heights.values[i], in.tree.values[i]);
        continue;
      }
      ++free;
      lowered += in.tree.values[i] - out.heights.values[i];
      // Filled at the end: a strictly lower edge neighbour everywhere.
      const double z = out.heights.values[i];
      const bool lower = out.heights.values[out.heights.at(c + 1, r)] < z ||
                         out.heights.values[out.heights.at(c - 1, r)] < z ||
                         out.heights.values[out.heights.at(c, r + 1)] < z ||
                         out.heights.values[out.heights.at(c, r - 1)] < z;
      ASSERT_TRUE(lower) << c << ", " << r;
    }
  EXPECT_GT(lowered / free, 1.0); // the erosion took material away
}

TEST(Evolution, DifferentSeedsDrawDifferentReceivers) {
  const EvolutionInput in = randomLand(7);
  EvolutionParams p;
  p.steps = 5;
  p.seed = 1;
  const EvolutionResult a = evolveLandscape(in, p);
  p.seed = 2;
  const EvolutionResult b = evolveLandscape(in, p);
  EXPECT_NE(a.heights.values, b.heights.values);
}

} // namespace
} // namespace strahler::landscape
