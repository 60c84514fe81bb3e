#include "sim/spring_network.h"

#include <gtest/gtest.h>

#include <limits>

#include "sim/input_error.h"
#include "test_meshes.h"

namespace {

using wobble::InputError;
using wobble::validate_spring_network;

void expect_refused(const wobble::SpringNetwork& network, const std::string& words) {
  try {
    validate_spring_network(network);
    FAIL() << "accepted a network that should be refused: " << words;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(SpringNetwork, AcceptsTheTestMeshes) {
  for (const auto& mesh : wobble::testing::all_test_meshes()) {
    EXPECT_NO_THROW(validate_spring_network(mesh.network)) << mesh.name;
  }
}

TEST(SpringNetwork, RefusesMalformedNetworksNamingTheProblem) {
  const wobble::SpringNetwork good = wobble::testing::chain_mesh(3).network;
  auto bad = good;
  bad.E(1, 1) = 9;
  expect_refused(bad, "spring 1 refers to vertex 9");
  bad = good;
  bad.E(2, 0) = bad.E(2, 1);
  expect_refused(bad, "joins vertex 3 to itself");
  bad = good;
  bad.m(2) = 0.0;
  expect_refused(bad, "vertex 2 has mass");
  bad = good;
  bad.m.resize(2);
  expect_refused(bad, "expected 4 masses");
  bad = good;
  bad.V(1, 1) = std::numeric_limits<double>::infinity();
  expect_refused(bad, "not finite");
  bad = good;
  bad.F.resize(1, 3);
  bad.F << 0, 1, 4;
  expect_refused(bad, "face 0 refers to vertex 4");
  bad = good;
  bad.V.resize(0, 3);
  expect_refused(bad, "no vertices");
}

}  // namespace
