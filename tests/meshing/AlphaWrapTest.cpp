// SPDX-License-Identifier: AGPL-3.0-or-later
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ExpectError.h"
#include "Shapes.h"
#include "tetskin/core/Error.h"
#include "tetskin/io/ObjFormat.h"
#include "tetskin/meshing/AlphaWrap.h"
#include "tetskin/meshing/SurfaceRepair.h"
#include "tetskin/spatial/TriangleDistance.h"

namespace tetskin {
namespace {

const std::string kData = TETSKIN_TEST_DATA_DIR;

// What a wrap must be: closed, 2-manifold, without self-intersections,
// wound outward (so repair has nothing to do but check it).
void expectClosedManifold(const SurfaceMesh& wrap) {
  EXPECT_GT(wrap.triangleCount(), 0);
  EXPECT_TRUE(boundaryLoops(wrap).empty());
  EXPECT_EQ(nonManifoldEdgeCount(wrap), 0);
  EXPECT_TRUE(findSelfIntersections(wrap, 1).empty());
  EXPECT_GT(enclosedVolume(wrap), 0.0);
}

TEST(AlphaWrap, ModeNamesRoundTrip) {
  for (WrapMode mode : {WrapMode::Never, WrapMode::Auto, WrapMode::Always})
    EXPECT_EQ(parseName<WrapMode>(toString(mode)), mode);
  EXPECT_FALSE(parseName<WrapMode>("sometimes"));
}

// A closed sphere's wrap lies outside it at about the offset: every wrap
// vertex within [offset - tolerance, offset + tolerance] of the sphere
// (CGAL places the wrap's vertices on the offset surface), and every
// sphere vertex inside the wrap, close to it.
TEST(AlphaWrap, WrapOfAClosedSphereLiesAtTheOffset) {
  const SurfaceMesh sphere = test::sphere({0, 0, 0}, 1.0, 24, 36);
  const double alpha = 0.1, offset = 0.02;
  const SurfaceMesh wrap = alphaWrap(sphere, alpha, offset, "sphere");
  expectClosedManifold(wrap);
  const WrapFidelity f = wrapFidelity(sphere, wrap);
  EXPECT_LE(f.wrapToInput.max, offset * 1.05);
  EXPECT_GE(f.wrapToInput.mean, offset * 0.9);
  // The sphere's vertices: at least the offset inside the wrap, and not
  // much more (the wrap's flat triangles cut a little closer).
  EXPECT_LE(f.inputToWrap.max, offset + 0.01);
  EXPECT_GT(f.inputToWrap.mean, 0.5 * offset);
  EXPECT_GT(enclosedVolume(wrap), enclosedVolume(sphere));
  EXPECT_NEAR(f.diagonal, std::sqrt(12.0), 1e-6);
}

// Inputs repair cannot close: each wraps into one closed surface.
TEST(AlphaWrap, BrokenInputsBecomeClosedManifoldSurfaces) {
  for (const char* name : {"bunny_holed.obj", "overlapping_spheres.obj", "soup_with_gaps.obj",
                           "nonmanifold_fins.obj", "inverted_part.obj", "open_sheet.obj"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh input = readObj(kData + "/" + name);
    const double diagonal = boundingBox(input).diagonal();
    const SurfaceMesh wrap = alphaWrap(input, diagonal / 30, diagonal / 300, name);
    expectClosedManifold(wrap);
  }
}

// A hole wider than alpha lets the wrap in: it coats the inside too, and
// the bunny cut open comes out a hollow skin about 2 offsets thick. With
// its holes closed first (wrapReady, as build does), the wrap encloses
// the body, and the holes show in the distances: wrap -> input is largest
// where the wrap closes a hole; input -> wrap stays near the offset.
TEST(AlphaWrap, HolesWiderThanAlphaAreClosedFirstAndShowInTheDistances) {
  const SurfaceMesh input = readObj(kData + "/bunny_holed.obj");
  const double diagonal = boundingBox(input).diagonal();
  const double alpha = diagonal / 50, offset = diagonal / 500;
  const SurfaceMesh coated = alphaWrap(input, alpha, offset, "bunny");
  EXPECT_LT(meanThickness(coated), 4 * offset);
  Index closed = 0;
  const SurfaceMesh filled = wrapReady(input, {}, &closed);
  EXPECT_EQ(closed, 3);  // the base's two, the ear's
  const SurfaceMesh wrap = alphaWrap(filled, alpha, offset, "bunny");
  expectClosedManifold(wrap);
  EXPECT_GT(meanThickness(wrap), 50 * offset);
  EXPECT_GT(enclosedVolume(wrap), 0.9 * enclosedVolume(filled));
  // (input -> wrap: about the offset, more where the wrap bridges a
  // concavity narrower than alpha.)
  const WrapFidelity f = wrapFidelity(input, wrap);
  EXPECT_LT(f.inputToWrap.mean, 2 * offset);
  EXPECT_LT(f.inputToWrap.max, alpha);
  EXPECT_GT(f.wrapToInput.max, 10 * offset);
}

TEST(AlphaWrap, AnOpenSheetBecomesAShellTwoOffsetsThick) {
  // (Its one hole, the rim, would take a patch as large as the sheet:
  // wrapReady leaves it open.)
  Index closed = -1;
  const SurfaceMesh sheet = wrapReady(readObj(kData + "/open_sheet.obj"), {}, &closed);
  EXPECT_EQ(closed, 0);
  const double offset = 0.05;
  const SurfaceMesh wrap = alphaWrap(sheet, 0.2, offset, "sheet");
  expectClosedManifold(wrap);
  EXPECT_NEAR(meanThickness(wrap), 2 * offset, 0.5 * offset);
}

TEST(AlphaWrap, NothingToWrapIsAClearError) {
  test::expectErrorAt([] { alphaWrap(readObj(kData + "/no_area.obj"), 0.1, 0.01, "flat.obj"); },
                      "flat.obj", 0,
                      "every triangle of the surface has zero area: there is nothing to wrap");
  test::expectErrorAt([] { alphaWrap(SurfaceMesh{}, 0.1, 0.01, "empty.obj"); }, "empty.obj", 0,
                      "the surface has no triangles");
  test::expectErrorAt(
      [] {
        alphaWrap(test::box({0, 0, 0}, {1, 1, 1}), 0, 0.01, "box");
      },
      "box", 0, "alpha must be a positive number");
  EXPECT_FALSE(hasArea(readObj(kData + "/no_area.obj")));
  EXPECT_TRUE(hasArea(test::box({0, 0, 0}, {1, 1, 1})));
}

}  // namespace
}  // namespace tetskin
