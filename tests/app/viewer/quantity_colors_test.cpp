#include "app/viewer/quantity_colors.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <vector>

#include "sim/contact/collider_contact_term.h"
#include "sim/contact/self_contact_term.h"
#include "sim/simulation.h"

namespace {

using wobble::ColorQuantity;

// Relative luminance of linear RGB (Rec. 709 weights).
float luminance(const Eigen::Vector3f& c) {
  return 0.2126f * c.x() + 0.7152f * c.y() + 0.0722f * c.z();
}

TEST(QuantityColors, StrainIsPositiveStretchedAndNegativeCompressed) {
  // Two springs of rest length 1 m and 2 m: the first stretched to 1.1 m, the second
  // compressed to 1.6 m.
  Eigen::MatrixXd V(4, 3);
  V << 0, 0, 0, 1.1, 0, 0, 0, 5, 0, 0, 6.6, 0;
  Eigen::MatrixXi E(2, 2);
  E << 0, 1, 2, 3;
  const Eigen::VectorXd r = Eigen::Vector2d(1.0, 2.0);
  Eigen::VectorXf strain;
  wobble::spring_strains(V, E, r, strain);
  ASSERT_EQ(strain.size(), 2);
  // Single-precision output of a double computation: 1e-6 is a few float roundings of 0.1.
  EXPECT_NEAR(strain[0], 0.1f, 1e-6f);
  EXPECT_NEAR(strain[1], -0.2f, 1e-6f);
}

TEST(QuantityColors, AVertexTakesTheMeanStrainOfItsSprings) {
  Eigen::MatrixXi E(2, 2);
  E << 0, 1, 1, 2;
  Eigen::VectorXf spring_values(2);
  spring_values << 0.1f, -0.3f;
  Eigen::VectorXf vertex_values, counts;
  // Vertex 3 has no spring.
  wobble::vertex_mean_of_springs(E, spring_values, 4, vertex_values, counts);
  ASSERT_EQ(vertex_values.size(), 4);
  EXPECT_FLOAT_EQ(vertex_values[0], 0.1f);
  EXPECT_FLOAT_EQ(vertex_values[1], -0.1f);
  EXPECT_FLOAT_EQ(vertex_values[2], -0.3f);
  EXPECT_EQ(vertex_values[3], 0.0f);
}

TEST(QuantityColors, SpeedIsTheLastStepsDisplacementOverDt) {
  Eigen::MatrixXd previous = Eigen::MatrixXd::Zero(2, 3);
  Eigen::MatrixXd current = previous;
  const double dt = 0.01;
  current.row(1) << 3.0 * dt, 4.0 * dt, 0.0;  // a 3-4-5 triangle: 5 m/s
  Eigen::VectorXf speed;
  wobble::vertex_speeds(current, previous, dt, speed);
  ASSERT_EQ(speed.size(), 2);
  EXPECT_EQ(speed[0], 0.0f);
  EXPECT_NEAR(speed[1], 5.0f, 1e-5f);  // float rounding of 5
}

TEST(QuantityColors, DivergingMapIsNeutralAtZeroBlueWhenCompressedRedWhenStretched) {
  const Eigen::Vector3f zero = wobble::diverging_color(0.0f);
  EXPECT_GT(zero.minCoeff(), 0.85f) << "near-white";
  EXPECT_LT(zero.maxCoeff() - zero.minCoeff(), 0.1f) << "nearly grey";
  const Eigen::Vector3f blue = wobble::diverging_color(-1.0f), red = wobble::diverging_color(1.0f);
  EXPECT_GT(blue.z(), 2.0f * blue.x());
  EXPECT_GT(blue.z(), 2.0f * blue.y());
  EXPECT_GT(red.x(), 5.0f * red.y());
  EXPECT_GT(red.x(), 5.0f * red.z());
  // Clamped beyond the range.
  EXPECT_TRUE(wobble::diverging_color(-7.0f).isApprox(blue));
  EXPECT_TRUE(wobble::diverging_color(3.0f).isApprox(red));
  // Lightness falls away from zero on both sides alike, within 0.04 of each other.
  for (float t = 0.0f; t <= 1.0f; t += 0.125f) {
    const float stretch = luminance(wobble::diverging_color(t));
    const float compression = luminance(wobble::diverging_color(-t));
    EXPECT_NEAR(stretch, compression, 0.04f) << t;
    EXPECT_LE(stretch, luminance(zero) + 1e-6f);
  }
}

TEST(QuantityColors, SequentialMapRisesFromDarkToBright) {
  EXPECT_LT(luminance(wobble::sequential_color(0.0f)), 0.05f);
  EXPECT_GT(luminance(wobble::sequential_color(1.0f)), 0.9f);
  float last = -1.0f;
  for (int i = 0; i <= 64; ++i) {
    const Eigen::Vector3f color = wobble::sequential_color(i / 64.0f);
    EXPECT_GT(luminance(color), last) << i;
    EXPECT_GE(color.minCoeff(), 0.0f);
    EXPECT_LE(color.maxCoeff(), 1.0f);
    last = luminance(color);
  }
  EXPECT_TRUE(wobble::sequential_color(-1.0f).isApprox(wobble::sequential_color(0.0f)));
  EXPECT_TRUE(wobble::sequential_color(2.0f).isApprox(wobble::sequential_color(1.0f)));
}

TEST(QuantityColors, RobustMaximumIgnoresTheTopPercentAndTheSign) {
  Eigen::VectorXf values(1000);
  for (int i = 0; i < 1000; ++i)
    values[i] = (i % 2 ? -1.0f : 1.0f) * static_cast<float>(i);
  values[500] = 1e6f;  // one spring torn at a dragged pin
  std::vector<float> scratch;
  const float maximum = wobble::robust_maximum(values, scratch);
  EXPECT_GE(maximum, 985.0f);
  EXPECT_LE(maximum, 995.0f);
  EXPECT_EQ(wobble::robust_maximum(Eigen::VectorXf(), scratch), 0.0f);
}

TEST(QuantityColors, RangeStartsAtTheFirstValueRisesFastFallsSlowlyAndKeepsItsFloor) {
  wobble::SmoothedRange range(0.01f);
  EXPECT_EQ(range.update(2.0f), 2.0f);
  const float up = range.update(4.0f) - 2.0f;
  EXPECT_NEAR(up, 2.0f * wobble::SmoothedRange::rise, 1e-6f);
  const float before = range.value();
  const float down = before - range.update(0.0f);
  EXPECT_NEAR(down, (before - 0.01f) * wobble::SmoothedRange::fall, 1e-6f);
  EXPECT_LT(down, up);
  for (int i = 0; i < 1000; ++i)
    range.update(0.0f);
  EXPECT_NEAR(range.value(), 0.01f, 1e-6f);
  range.restart();
  EXPECT_EQ(range.update(0.5f), 0.5f);
}

TEST(QuantityColors, NamesCycleAndParse) {
  EXPECT_EQ(wobble::next_color_quantity(ColorQuantity::material), ColorQuantity::strain);
  EXPECT_EQ(wobble::next_color_quantity(ColorQuantity::strain), ColorQuantity::speed);
  EXPECT_EQ(wobble::next_color_quantity(ColorQuantity::speed), ColorQuantity::contacts);
  EXPECT_EQ(wobble::next_color_quantity(ColorQuantity::contacts), ColorQuantity::volume);
  EXPECT_EQ(wobble::next_color_quantity(ColorQuantity::volume), ColorQuantity::material);
  for (ColorQuantity q : {ColorQuantity::material, ColorQuantity::strain, ColorQuantity::speed,
                          ColorQuantity::contacts, ColorQuantity::volume})
    EXPECT_EQ(wobble::color_quantity_named(wobble::color_quantity_name(q)), q);
  EXPECT_FALSE(wobble::color_quantity_named("stress"));
  EXPECT_FALSE(wobble::color_quantity_named("Strain"));
}

// Two tetrahedra sharing a face: the first doubled in size (volume × 8), the second turned inside
// out through that face (its apex mirrored); a vertex of both takes the mean of the two changes.
TEST(QuantityColors, VolumeChangeIsEachTetrahedronsAtItsCorners) {
  Eigen::MatrixXd rest(5, 3);
  rest << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1;
  Eigen::MatrixXi T(2, 4);
  T << 0, 1, 2, 3, 0, 2, 1, 4;
  Eigen::MatrixXd now = rest;
  now.row(3) = Eigen::RowVector3d(0, 0, 2);
  now.row(1) = Eigen::RowVector3d(2, 0, 0);
  now.row(2) = Eigen::RowVector3d(0, 2, 0);
  now.row(4) = Eigen::RowVector3d(0, 0, 1);  // the second's apex through the face: inverted
  Eigen::VectorXf change, counts;
  wobble::vertex_volume_changes(now, rest, T, change, counts);
  ASSERT_EQ(change.size(), 5);
  EXPECT_NEAR(change[3], 7.0f, 1e-5f);  // only in the first: 8 times its volume
  // The second: corners 0, 2·e₁, 2·e₂ and +e₃ where −e₃ was: −4 times its rest volume.
  EXPECT_NEAR(change[4], -5.0f, 1e-5f);
  EXPECT_NEAR(change[0], 1.0f, 1e-5f);  // (7 − 5)/2
  // Without tetrahedra every vertex is neutral.
  wobble::vertex_volume_changes(now, rest, Eigen::MatrixXi(0, 4), change, counts);
  EXPECT_EQ(change.size(), 5);
  EXPECT_EQ(change.cwiseAbs().maxCoeff(), 0.0f);
}

TEST(QuantityColors, LegendNumbersHaveTwoSignificantDigits) {
  EXPECT_EQ(wobble::two_significant_digits(2.14f), "2.1");
  EXPECT_EQ(wobble::two_significant_digits(0.0213f), "0.021");
  EXPECT_EQ(wobble::two_significant_digits(34.4f), "34");
  EXPECT_EQ(wobble::two_significant_digits(123.0f), "123");
  EXPECT_EQ(wobble::two_significant_digits(0.0f), "0");
}

// A chain of two springs along x, 1 m each at rest, the first vertex pinned.
wobble::Simulation chain() {
  wobble::SpringNetwork network;
  network.V.resize(3, 3);
  network.V << 0, 0, 0, 1, 0, 0, 2, 0, 0;
  network.E.resize(2, 2);
  network.E << 0, 1, 1, 2;
  network.m = Eigen::VectorXd::Constant(3, 0.1);
  return wobble::Simulation(network, {0}, wobble::SimulationParams());
}

TEST(QuantityColors, ColoursAStretchedSpringRedAndACompressedOneBlue) {
  wobble::Simulation simulation = chain();
  Eigen::MatrixXd p = simulation.positions();
  p(1, 0) = 1.2;  // first spring +20%, second −20%
  simulation.set_state(p, p);
  wobble::QuantityColors colors;
  colors.update(ColorQuantity::strain, simulation);
  EXPECT_NEAR(colors.range(), 0.2f, 1e-5f);
  ASSERT_EQ(colors.spring_colors().size(), 6u);
  ASSERT_EQ(colors.vertex_colors().size(), 9u);
  const Eigen::Map<const Eigen::Vector3f> stretched(colors.spring_colors().data());
  const Eigen::Map<const Eigen::Vector3f> compressed(colors.spring_colors().data() + 3);
  EXPECT_TRUE(stretched.isApprox(wobble::diverging_color(1.0f), 1e-4f));
  EXPECT_TRUE(compressed.isApprox(wobble::diverging_color(-1.0f), 1e-4f));
  // The middle vertex is the mean of +20% and −20%: neutral.
  const Eigen::Map<const Eigen::Vector3f> middle(colors.vertex_colors().data() + 3);
  EXPECT_TRUE(middle.isApprox(wobble::diverging_color(0.0f), 1e-4f));

  // Springs that are not drawn get no colours; the vertices still do.
  colors.update(ColorQuantity::strain, simulation, /*with_springs=*/false);
  EXPECT_TRUE(colors.spring_colors().empty());
  EXPECT_EQ(colors.vertex_colors().size(), 9u);

  colors.update(ColorQuantity::material, simulation);
  EXPECT_TRUE(colors.vertex_colors().empty());
  EXPECT_TRUE(colors.spring_colors().empty());
}

TEST(QuantityColors, TwoShapesPaintedInOneRangeShowTheSameStrainInTheSameColour) {
  // Left +10%/−10%, right +20%/−20%: painted in the larger range, the left's stretched spring
  // is half-way up the map rather than at its end.
  wobble::Simulation left = chain(), right = chain();
  Eigen::MatrixXd p = left.positions();
  p(1, 0) = 1.1;
  left.set_state(p, p);
  p(1, 0) = 1.2;
  right.set_state(p, p);
  wobble::QuantityColors left_colors, right_colors;
  left_colors.measure(ColorQuantity::strain, left);
  right_colors.measure(ColorQuantity::strain, right);
  EXPECT_NEAR(left_colors.measured_range(), 0.1f, 1e-5f);
  const float range = std::max(left_colors.measured_range(), right_colors.measured_range());
  left_colors.paint(left, range, true);
  right_colors.paint(right, range, true);
  EXPECT_EQ(left_colors.range(), range);
  const Eigen::Map<const Eigen::Vector3f> left_stretched(left_colors.spring_colors().data());
  const Eigen::Map<const Eigen::Vector3f> right_stretched(right_colors.spring_colors().data());
  EXPECT_TRUE(left_stretched.isApprox(wobble::diverging_color(0.5f), 1e-4f));
  EXPECT_TRUE(right_stretched.isApprox(wobble::diverging_color(1.0f), 1e-4f));
}

TEST(QuantityColors, ColoursSpeedFromDarkAtRestToBrightAtTheRange) {
  wobble::Simulation simulation = chain();
  const Eigen::MatrixXd p = simulation.positions();
  Eigen::MatrixXd previous = p;
  const double dt = simulation.params().dt;
  previous(2, 1) = p(2, 1) - 2.0 * dt;  // the end moves up at 2 m/s, the rest is still
  simulation.set_state(p, previous);
  wobble::QuantityColors colors;
  colors.update(ColorQuantity::speed, simulation);
  // The 99th percentile of {0, 0, 2} is interpolated down to the second-largest: the floor.
  EXPECT_NEAR(colors.range(), wobble::QuantityColors::speed_floor, 1e-6f);
  const Eigen::Map<const Eigen::Vector3f> still(colors.vertex_colors().data());
  const Eigen::Map<const Eigen::Vector3f> moving(colors.vertex_colors().data() + 6);
  EXPECT_TRUE(still.isApprox(wobble::sequential_color(0.0f), 1e-5f));
  EXPECT_TRUE(moving.isApprox(wobble::sequential_color(1.0f), 1e-5f));
  // The second spring: the mean of 0 and 2 m/s, still above the range.
  const Eigen::Map<const Eigen::Vector3f> spring(colors.spring_colors().data() + 3);
  EXPECT_TRUE(spring.isApprox(wobble::sequential_color(1.0f), 1e-5f));
}

// Colouring by contacts.

Eigen::Vector3f color_of(const std::vector<float>& colors, int i) {
  return Eigen::Vector3f(colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]);
}

TEST(QuantityColors, ContactColoursFollowTheFlagsSelfFirst) {
  const std::vector<char> self = {0, 1, 0, 1, 0}, collider = {0, 0, 1, 1, 0};
  std::vector<float> colors;
  wobble::contact_colors(self, collider, 5, colors);
  ASSERT_EQ(colors.size(), 15u);
  EXPECT_EQ(color_of(colors, 0), wobble::contact_free_color());
  EXPECT_EQ(color_of(colors, 1), wobble::self_contact_color());
  EXPECT_EQ(color_of(colors, 2), wobble::collider_contact_color());
  EXPECT_EQ(color_of(colors, 3), wobble::self_contact_color());  // both: the self contact
  EXPECT_EQ(color_of(colors, 4), wobble::contact_free_color());
  // The three colours differ, or the picture would say nothing.
  EXPECT_NE(wobble::self_contact_color(), wobble::collider_contact_color());
  EXPECT_NE(wobble::self_contact_color(), wobble::contact_free_color());
  EXPECT_NE(wobble::collider_contact_color(), wobble::contact_free_color());

  // No flags yet (before the first step, or no collider), or flags of another shape: none set.
  wobble::contact_colors({}, {0, 1}, 5, colors);
  ASSERT_EQ(colors.size(), 15u);
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(color_of(colors, i), wobble::contact_free_color()) << i;
}

// Three triangles of one surface: two pinned side by side, and a smaller free one 5 cm above the
// first, falling through it within a step unless self-collision holds it a thickness away. The
// second pinned triangle's far vertex 6 is nowhere near it.
wobble::Simulation falling_triangle() {
  wobble::SpringNetwork network;
  network.V.resize(7, 3);
  network.V << 0, 0, 0, 1, 0, 0, 0, 0, 1,              //
      0.2, 0.05, 0.2, 0.4, 0.05, 0.2, 0.2, 0.05, 0.4,  //
      3, 0, 0;
  network.E.resize(8, 2);
  network.E << 0, 1, 1, 2, 2, 0, 3, 4, 4, 5, 5, 3, 1, 6, 6, 2;
  network.F.resize(3, 3);
  network.F << 0, 2, 1, 3, 5, 4, 1, 2, 6;
  network.m = Eigen::VectorXd::Constant(7, 0.1);
  wobble::SimulationParams params;
  params.self_collision.on = true;
  params.self_collision.thickness = 0.01;
  Eigen::MatrixXd velocity = Eigen::MatrixXd::Zero(7, 3);
  velocity.block(3, 1, 3, 1).setConstant(-6.0);  // 0.1 m in a step of 1/60 s
  return wobble::Simulation(network, {0, 1, 2, 6}, params, velocity);
}

TEST(QuantityColors, ContactsGiveTheSelfContactColourExactlyToFlaggedVertices) {
  wobble::Simulation simulation = falling_triangle();
  wobble::QuantityColors colors;
  // Before the first step no vertex is in contact.
  colors.update(ColorQuantity::contacts, simulation);
  ASSERT_EQ(colors.vertex_colors().size(), 21u);
  for (int i = 0; i < 7; ++i)
    EXPECT_EQ(color_of(colors.vertex_colors(), i), wobble::contact_free_color()) << i;

  // Self-contact slows the triangle as it nears the other (its bounds) and then holds it on:
  // step until the pair presses.
  for (int step = 0; step < 20 && simulation.term<wobble::SelfContactTerm>()->contact_count() == 0;
       ++step)
    ASSERT_EQ(simulation.step(), wobble::StepStatus::ok);
  const std::vector<char>& flags = wobble::self_contact_vertices(simulation.terms());
  ASSERT_EQ(flags.size(), 7u);
  ASSERT_TRUE(flags[3] && flags[4] && flags[5]) << "the upper triangle is held above the lower";
  ASSERT_FALSE(flags[6]) << "far from the falling triangle";
  colors.update(ColorQuantity::contacts, simulation);
  EXPECT_EQ(colors.range(), 0.0f);
  ASSERT_EQ(colors.vertex_colors().size(), 21u);
  for (int i = 0; i < 7; ++i) {
    EXPECT_EQ(color_of(colors.vertex_colors(), i),
              flags[i] ? wobble::self_contact_color() : wobble::contact_free_color())
        << i;
  }
  // A spring is coloured as its first end in contact.
  ASSERT_EQ(colors.spring_colors().size(), 24u);
  const Eigen::MatrixXi& E = simulation.rest().E;
  for (int e = 0; e < 8; ++e) {
    const bool touching = flags[E(e, 0)] || flags[E(e, 1)];
    EXPECT_EQ(color_of(colors.spring_colors(), e),
              touching ? wobble::self_contact_color() : wobble::contact_free_color())
        << e;
  }
}

TEST(QuantityColors, ContactsGiveTheColliderColourExactlyToVerticesOnACollider) {
  // The chain hanging from a pin 1 m up down to the ground: its free vertices, lying on it, fall
  // into it and are pushed back; the pin is far above it.
  wobble::SpringNetwork network;
  network.V.resize(3, 3);
  network.V << 0, 1, 0, 1, 0, 0, 2, 0, 0;
  network.E.resize(2, 2);
  network.E << 0, 1, 1, 2;
  network.m = Eigen::VectorXd::Constant(3, 0.1);
  wobble::SimulationParams params;
  wobble::Collider ground;
  ground.type = wobble::ColliderType::ground;
  ground.height = 0.0;
  params.contact.colliders.push_back(ground);
  wobble::Simulation simulation(network, {0}, params);
  ASSERT_EQ(simulation.step(), wobble::StepStatus::ok);
  const std::vector<char>& flags = wobble::collider_contact_vertices(simulation.terms());
  ASSERT_EQ(flags.size(), 3u);
  ASSERT_GT(simulation.term<wobble::ColliderContactTerm>()->colliders().contact_count(), 0);
  wobble::QuantityColors colors;
  colors.update(ColorQuantity::contacts, simulation);
  ASSERT_EQ(colors.vertex_colors().size(), 9u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(color_of(colors.vertex_colors(), i),
              flags[i] ? wobble::collider_contact_color() : wobble::contact_free_color())
        << i;
  }
  EXPECT_FALSE(flags[0]) << "1 m above the ground";
  EXPECT_TRUE(flags[2]);
}

}  // namespace
