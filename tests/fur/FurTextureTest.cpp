// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>

#include "tetskin/core/Error.h"
#include "tetskin/fur/FurTexture.h"

namespace tetskin {
namespace {

double hairShare(const FurTexture& t) {
  std::size_t hairs = 0;
  for (float a : t.hairLength) hairs += a > 0;
  return static_cast<double>(hairs) / static_cast<double>(t.hairLength.size());
}

TEST(FurTexture, HairDensityMatchesTheParameter) {
  for (double density : {0.1, 0.35, 0.6, 0.9}) {
    FurTextureOptions o;
    o.size = 256;
    o.density = density;
    const FurTexture t = generateFurTexture(o);
    // Binomial: 4 standard deviations of 65536 draws.
    const double sigma = std::sqrt(density * (1 - density) / 65536.0);
    EXPECT_NEAR(hairShare(t), density, 4 * sigma) << density;
  }
  FurTextureOptions none, all;
  none.density = 0;
  all.density = 1;
  EXPECT_EQ(hairShare(generateFurTexture(none)), 0.0);
  EXPECT_EQ(hairShare(generateFurTexture(all)), 1.0);
}

TEST(FurTexture, GapsStayTransparentAndHairsThinOutAndEndAtTheirLength) {
  FurTextureOptions o;
  o.size = 64;
  o.layers = 16;
  const FurTexture t = generateFurTexture(o);
  ASSERT_EQ(t.rgba.size(), 4u * 64 * 64 * 16);
  for (int y = 0; y < t.size; ++y)
    for (int x = 0; x < t.size; ++x) {
      const float length = t.hairLength[static_cast<std::size_t>(y * t.size + x)];
      int previous = 256;
      for (int l = 0; l < t.layers; ++l) {
        const int a = t.alpha(x, y, l);
        if (length == 0) {
          ASSERT_EQ(a, 0);
        }
        ASSERT_LE(a, previous) << "alpha must not grow toward the tip";
        if (t.layerHeight(l) >= length) {
          ASSERT_EQ(a, 0) << "a hair ends at its length";
        }
        previous = a;
      }
      if (length > 0) {
        EXPECT_GT(t.alpha(x, y, 0), 200);  // opaque at the root
      }
    }
}

TEST(FurTexture, ColourIsDarkerTowardTheRoot) {
  FurTextureOptions o;
  o.size = 32;
  o.rootShade = 0.3;
  const FurTexture t = generateFurTexture(o);
  double previous = -1;
  for (int l = 0; l < t.layers; ++l) {
    double sum = 0;
    for (int i = 0; i < t.size * t.size; ++i)
      sum += t.rgba[4 * (static_cast<std::size_t>(l) * t.size * t.size + i)];
    const double mean = sum / (t.size * t.size) / 255.0;
    EXPECT_GT(mean, previous);
    previous = mean;
  }
  // Root layer about rootShade x (0.88..1 tint), tip near the tint.
  double root = 0;
  for (int i = 0; i < t.size * t.size; ++i) root += t.rgba[4 * static_cast<std::size_t>(i)];
  EXPECT_NEAR(root / (t.size * t.size) / 255.0, 0.3 * 0.94, 0.03);
}

TEST(FurTexture, SameSeedSameTextureOtherSeedOther) {
  FurTextureOptions a;
  a.size = 32;
  FurTextureOptions b = a;
  b.seed = 2;
  EXPECT_EQ(generateFurTexture(a).rgba, generateFurTexture(a).rgba);
  EXPECT_NE(generateFurTexture(a).rgba, generateFurTexture(b).rgba);
}

TEST(FurTexture, HairOpacityFallsFromRootToTip) {
  EXPECT_DOUBLE_EQ(hairOpacity(0.8, 0.0), 1.0);
  EXPECT_GT(hairOpacity(0.8, 0.2), hairOpacity(0.8, 0.6));
  EXPECT_EQ(hairOpacity(0.8, 0.8), 0.0);
  EXPECT_EQ(hairOpacity(0.0, 0.1), 0.0);
}

TEST(FurTexture, RejectsParametersOutOfRange) {
  FurTextureOptions o;
  o.size = 4;
  EXPECT_THROW(generateFurTexture(o), Error);
  o = {};
  o.density = 1.5;
  EXPECT_THROW(generateFurTexture(o), Error);
  o = {};
  o.layers = 1;
  EXPECT_THROW(generateFurTexture(o), Error);
}

}  // namespace
}  // namespace tetskin
