// SPDX-License-Identifier: AGPL-3.0-or-later
// A recorded run read at points (RunProbe.h): frames of an affine motion x
// = F X + b, which linear tetrahedra hold exactly, give every point's
// displacement (F - I) X + b to round-off wherever it lies in its element;
// the stress is the point's element's; a point outside the mesh is refused
// by its name.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "ExpectError.h"
#include "Frames.h"
#include "Shapes.h"
#include "TestFiles.h"
#include "tetskin/session/RunProbe.h"
#include "tetskin/vtkio/RunRecorder.h"

namespace tetskin::test {
namespace {

TEST(RunProbe, InterpolatesAnAffineMotionExactlyAndTakesTheElementsStress) {
  ScratchDir dir;
  const TetMesh rest = tetGrid(3, 2, 2, {3, 2, 2});
  const Eigen::Matrix3d F =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix() *
      Eigen::Vector3d(1.1, 0.95, 1.02).asDiagonal();
  const Eigen::Vector3d b(0.3, -0.2, 0.1);
  RunRecorder recorder(dir / "run.pvd");
  for (int frame = 0; frame < 3; ++frame) {
    const double s = 0.5 * frame;  // the motion's share at this frame
    Points3 positions = rest.nodes;
    for (Index v = 0; v < rest.nodeCount(); ++v) {
      const Eigen::Vector3d X = rest.nodes.row(v).transpose();
      positions.row(v) = (X + s * ((F - Eigen::Matrix3d::Identity()) * X + b)).transpose();
    }
    FrameFields fields = unloadedFrame(rest, positions);
    fields.stress.resize(rest.elementCount(), 6);
    for (Index e = 0; e < rest.elementCount(); ++e)
      for (int c = 0; c < 6; ++c)
        fields.stress(e, c) = 100.0 * frame + static_cast<double>(e) + 0.1 * c;
    recorder.addFrame(0.1 * frame, rest, fields, 0);
  }
  Points3 points(3, 3);
  points << 0.25, 0.3, 1.7,  // inside
      1.5, 1.0, 1.0,         // on shared faces
      3.0, 2.0, 0.0;         // a corner
  const RunProbe probe = probeRun(dir / "run.pvd", points, {"a", "b", "c"});
  ASSERT_EQ(probe.times.size(), 3u);
  EXPECT_DOUBLE_EQ(probe.times[2], 0.2);
  for (std::size_t f = 0; f < 3; ++f) {
    const double s = 0.5 * static_cast<double>(f);
    for (Index p = 0; p < points.rows(); ++p) {
      const Eigen::Vector3d X = points.row(p).transpose();
      const Eigen::Vector3d expected = s * ((F - Eigen::Matrix3d::Identity()) * X + b);
      EXPECT_LT((probe.displacements[f].row(p).transpose() - expected).norm(), 1e-12)
          << "frame " << f << ", point " << p;
      const int e = probe.elements[static_cast<std::size_t>(p)];
      EXPECT_EQ(probe.stresses[f](p, 0), 100.0 * static_cast<double>(f) + static_cast<double>(e));
      EXPECT_EQ(probe.stresses[f](p, 5),
                100.0 * static_cast<double>(f) + static_cast<double>(e) + 0.5);
    }
  }
  Points3 outside(1, 3);
  outside << 3.5, 1, 1;
  EXPECT_EQ(errorText([&] { probeRun(dir / "run.pvd", outside, {"pts.txt:4"}); }),
            "pts.txt:4: the point 3.5,1,1 lies outside the run's control mesh (0.5 from its "
            "nearest element)");
}

}  // namespace
}  // namespace tetskin::test
