#pragma once

#include "test_worlds.h"

#include "strahler/geometry/polygon_index.h"
#include "strahler/input/world_spec.h"
#include "strahler/network/network_growth.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace strahler::network {

/// A spec, its land and the network grown on it.
struct GrownWorld {
  input::WorldSpec spec;
  std::unique_ptr<geometry::PolygonIndex> land;
  RiverNetwork network;
};

/// generateNetwork on `spec` with `grower` (a failure is a test failure and an empty network).
inline GrownWorld grow(input::WorldSpec spec,
                       input::NetworkGrower grower = input::NetworkGrower::kGrammar) {
  spec.params.grower = grower;
  GrownWorld w{std::move(spec), nullptr, {}};
  w.land = std::make_unique<geometry::PolygonIndex>(w.spec.land);
  auto net = generateNetwork(w.spec, *w.land);
  EXPECT_TRUE(net.ok()) << (net.ok() ? "" : net.error().message);
  if (net.ok())
    w.network = std::move(net).value();
  return w;
}

/// The default island ("default") or Mallorca ("mallorca") grown by `grower`, each grown once
/// per test process, when first asked for (the tests run on one thread).
inline const GrownWorld& grownWorld(input::NetworkGrower grower, const std::string& name) {
  static std::unique_ptr<GrownWorld> worlds[2][2];
  const bool dla = grower == input::NetworkGrower::kDla, mallorca = name == "mallorca";
  std::unique_ptr<GrownWorld>& w = worlds[dla ? 1 : 0][mallorca ? 1 : 0];
  if (!w)
    w = std::make_unique<GrownWorld>(
        grow(mallorca ? test_support::mallorcaSpec() : test_support::defaultIslandSpec(), grower));
  return *w;
}

} // namespace strahler::network
