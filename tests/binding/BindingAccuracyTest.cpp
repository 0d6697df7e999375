// SPDX-License-Identifier: AGPL-3.0-or-later
// How well a bound surface follows its control mesh: rigid motions (must be
// exact with the Normal offset) and smooth analytic deformations applied both
// to the control nodes and, directly, to the surface (reported as RMS error).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>

#include "SampleData.h"
#include "tetskin/binding/BindSurface.h"
#include "tetskin/deformation/SurfaceDeformer.h"
#include "tetskin/io/Dataset.h"
#include "tetskin/io/ObjFormat.h"

namespace tetskin {
namespace {

using test::kSampleData;
using test::sampleDataset;
using Map = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;

Points3 apply(const Points3& points, const Map& f) {
  Points3 out(points.rows(), 3);
  for (Index i = 0; i < points.rows(); ++i) out.row(i) = f(points.row(i).transpose()).transpose();
  return out;
}

struct Errors {
  double max = 0, rms = 0;
};

// Error of the deformed surface against the map applied to the surface
// itself, relative to the surface's bounding-box diagonal.
Errors followError(const SurfaceMesh& surface, const Dataset& d, int level, BindingMethod method,
                   OffsetMode offset, const Map& f) {
  BindingOptions options;
  options.method = method;
  options.offset = offset;
  const SurfaceBinding b = bindSurface(surface, d.mesh, level, options);
  SurfaceDeformer deformer(surface, b, d.mesh.nodes);
  Points3 positions, normals;
  deformer.deform(apply(d.mesh.nodes, f), positions, normals);
  const Points3 expected = apply(surface.positions, f);
  const double diagonal = boundingBox(surface.positions).diagonal();
  Errors e;
  for (Index v = 0; v < positions.rows(); ++v) {
    const double err = (positions.row(v) - expected.row(v)).norm() / diagonal;
    e.max = std::max(e.max, err);
    e.rms += err * err;
  }
  e.rms = std::sqrt(e.rms / static_cast<double>(positions.rows()));
  return e;
}

class BindingAccuracy : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    surface_ = new SurfaceMesh(readObj(kSampleData + "bunny_8k.obj"));
  }
  static void TearDownTestSuite() { delete surface_; }
  static SurfaceMesh* surface_;
};
SurfaceMesh* BindingAccuracy::surface_ = nullptr;

const Map kRigid = [](const Eigen::Vector3d& p) {
  const Eigen::AngleAxisd r(35.0 * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized());
  return Eigen::Vector3d(r * p + Eigen::Vector3d(3, -1, 2));
};

TEST_F(BindingAccuracy, RigidMotionIsExactWithTheNormalOffset) {
  for (int level : {0, 2})
    for (BindingMethod method :
         {BindingMethod::Closest, BindingMethod::Seed, BindingMethod::Embed}) {
      const Errors e =
          followError(*surface_, sampleDataset(), level, method, OffsetMode::Normal, kRigid);
      EXPECT_LT(e.max, 1e-5) << toString(method) << " level " << level;
    }
}

TEST_F(BindingAccuracy, TheReportsDisplacementFormulaIsNotRotationInvariant) {
  // Formula 4.1 adds interpolated displacements to the rest position: the
  // offset from the control triangle does not rotate with it.
  const Errors normal = followError(*surface_, sampleDataset(), 0, BindingMethod::Closest,
                                    OffsetMode::Normal, kRigid);
  const Errors displacement = followError(*surface_, sampleDataset(), 0, BindingMethod::Closest,
                                          OffsetMode::Displacement, kRigid);
  std::printf(
      "35 deg rotation, level 0, closest: max error / diagonal: normal %.2e, displacement %.2e\n",
      normal.max, displacement.max);
  EXPECT_GT(displacement.max, 1e-3);
  EXPECT_GT(displacement.max, 1e4 * normal.max);
}

// Why `tetskin bind --method embed` takes no --offset: the weights are the
// vertex's own (unclamped) barycentric coordinates, so the displacement
// offset's shift, rest minus the weighted rest nodes, is zero and both
// offsets place every vertex alike, here under an arbitrary non-affine map.
TEST_F(BindingAccuracy, EitherOffsetDeformsAnEmbeddedVertexAlike) {
  const Map wobble = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(p.x() + 0.3 * std::sin(p.y()), p.y() * (1 + 0.1 * p.z()),
                           p.z() + 0.2 * p.x() * p.x());
  };
  const Dataset& d = sampleDataset();
  const Points3 control = apply(d.mesh.nodes, wobble);
  for (int level : {0, 2}) {
    Points3 deformed[2], normals;
    for (OffsetMode offset : {OffsetMode::Normal, OffsetMode::Displacement}) {
      BindingOptions options;
      options.method = BindingMethod::Embed;
      options.offset = offset;
      const SurfaceBinding b = bindSurface(*surface_, d.mesh, level, options);
      SurfaceDeformer(*surface_, b, d.mesh.nodes)
          .deform(control, deformed[offset == OffsetMode::Displacement], normals);
    }
    const double diagonal = boundingBox(surface_->positions).diagonal();
    EXPECT_LT((deformed[0] - deformed[1]).cwiseAbs().maxCoeff(), 1e-12 * diagonal)
        << "level " << level;
  }
}

TEST_F(BindingAccuracy, SmoothDeformationsReportTheirError) {
  const Map twist = [](const Eigen::Vector3d& p) {
    const double angle = 0.06 * p.y();  // about 33 degrees over the bunny's height
    return Eigen::Vector3d(std::cos(angle) * p.x() - std::sin(angle) * p.z(), p.y(),
                           std::sin(angle) * p.x() + std::cos(angle) * p.z());
  };
  const Map bend = [](const Eigen::Vector3d& p) {
    const double kappa = 0.08, rho = 1.0 / kappa, phi = kappa * p.y();
    return Eigen::Vector3d(rho - (rho - p.x()) * std::cos(phi), (rho - p.x()) * std::sin(phi),
                           p.z());
  };
  std::printf("RMS (max) error / surface diagonal, bunny_8k on the sample dataset\n");
  std::printf("%-6s %-6s %-8s %-22s %-22s\n", "map", "level", "method", "offset normal",
              "offset displacement");
  for (const auto& [name, f] : {std::pair<const char*, Map>{"twist", twist}, {"bend", bend}})
    for (int level : {0, 2})
      for (BindingMethod method :
           {BindingMethod::Closest, BindingMethod::Seed, BindingMethod::Embed}) {
        const Errors n =
            followError(*surface_, sampleDataset(), level, method, OffsetMode::Normal, f);
        const Errors d =
            followError(*surface_, sampleDataset(), level, method, OffsetMode::Displacement, f);
        std::printf("%-6s %-6d %-8s %.2e (%.2e)      %.2e (%.2e)\n", name, level, toString(method),
                    n.rms, n.max, d.rms, d.max);
        // Linear interpolation over a coarse mesh cannot follow a curved map
        // exactly, but it must stay close.
        EXPECT_LT(n.rms, 0.01);
        EXPECT_LT(d.rms, 0.02);
      }
}

}  // namespace
}  // namespace tetskin
