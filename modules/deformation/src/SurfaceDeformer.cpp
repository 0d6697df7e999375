// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/deformation/SurfaceDeformer.h"

#include <Eigen/Geometry>
#include <string>

#include "tetskin/core/Error.h"
#include "tetskin/core/Parallel.h"

namespace tetskin {

SurfaceDeformer::SurfaceDeformer(const SurfaceMesh& restSurface, const SurfaceBinding& binding,
                                 const Points3& controlRest, const std::string& bindingName)
    : offset_(binding.offset),
      controls_(binding.controlsPerVertex()),
      triangles_(restSurface.triangles),
      adjacency_(vertexTriangleAdjacency(restSurface.triangles, restSurface.vertexCount())),
      faceScratch_(restSurface.triangleCount(), 3) {
  validateBinding(binding, restSurface.vertexCount(), controlRest.rows(), bindingName);
  records_.resize(static_cast<std::size_t>(restSurface.vertexCount()));
  for (Index v = 0; v < restSurface.vertexCount(); ++v) {
    Record& r = records_[static_cast<std::size_t>(v)];
    for (int c = 0; c < 4; ++c) {
      r.ids[c] = c < controls_ ? binding.controlIds(v, c) : binding.controlIds(v, 0);
      r.w[c] = c < controls_ ? binding.weights(v, c) : 0.0;
      maxControlId_ = std::max<Index>(maxControlId_, r.ids[c]);
    }
    r.d = binding.distance[v];
  }
  if (offset_ == OffsetMode::Displacement)
    shifts_ = displacementShifts(binding, restSurface.positions, controlRest);
}

Points3 displacementShifts(const SurfaceBinding& binding, const Points3& restSurface,
                           const Points3& controlRest) {
  Points3 shifts = restSurface;
  for (Index v = 0; v < shifts.rows(); ++v)
    for (int c = 0; c < binding.controlsPerVertex(); ++c)
      shifts.row(v) -= binding.weights(v, c) * controlRest.row(binding.controlIds(v, c));
  return shifts;
}

void SurfaceDeformer::deformPositions(ConstPoints3Ref control, Points3& positions) const {
  if (positions.rows() != vertexCount()) positions.resize(vertexCount(), 3);
  deformPositions(control, Points3Ref(positions));
}

void SurfaceDeformer::deformPositions(ConstPoints3Ref control, Points3Ref positions) const {
  if (control.rows() <= maxControlId_)
    throw Error("the control state has " + std::to_string(control.rows()) +
                " nodes, but the binding refers to node " + std::to_string(maxControlId_));
  requireRows("positions to deform into", positions.rows(), vertexCount(), "surface vertices");
  const Record* records = records_.data();
  const double* x = control.data();
  const Index controlStride = control.outerStride();
  double* out = positions.data();
  const Index stride = positions.outerStride();
  auto node = [x, controlStride](int id) {
    return Eigen::Map<const Eigen::Vector3d>(x + controlStride * id);
  };
  auto kernel = [&](const IndexRange<Index>& range) {
    for (Index v = range.begin(); v != range.end(); ++v) {
      const Record& r = records[v];
      Eigen::Map<Eigen::Vector3d> p(out + stride * v);
      if (offset_ == OffsetMode::Displacement) {
        p = shifts_.row(v).transpose();
        for (int c = 0; c < controls_; ++c) p += r.w[c] * node(r.ids[c]);
      } else if (controls_ == 4) {
        p = r.w[0] * node(r.ids[0]) + r.w[1] * node(r.ids[1]) + r.w[2] * node(r.ids[2]) +
            r.w[3] * node(r.ids[3]);
      } else {
        const Eigen::Vector3d a = node(r.ids[0]), b = node(r.ids[1]), c = node(r.ids[2]);
        const Eigen::Vector3d n = (b - a).cross(c - a);
        const double length = n.norm();
        p = r.w[0] * a + r.w[1] * b + r.w[2] * c;
        if (length > 0) p += (r.d / length) * n;
      }
    }
  };
  parallelFor<Index>(0, vertexCount(), 4096, kernel);
}

void SurfaceDeformer::deform(ConstPoints3Ref control, Points3& positions, Points3& normals) {
  if (positions.rows() != vertexCount()) positions.resize(vertexCount(), 3);
  if (normals.rows() != vertexCount()) normals.resize(vertexCount(), 3);
  deform(control, Points3Ref(positions), Points3Ref(normals));
}

void SurfaceDeformer::deform(ConstPoints3Ref control, Points3Ref positions, Points3Ref normals) {
  requireRows("normals to deform into", normals.rows(), vertexCount(), "surface vertices");
  deformPositions(control, positions);
  computeVertexNormals(positions, triangles_, adjacency_, faceScratch_, normals);
}

std::size_t SurfaceDeformer::bytesPerFrame() const {
  const std::size_t n = records_.size();
  // records in, positions out; normals: positions in per face, face normals out
  // and back in, adjacency in, normals out.
  return n * sizeof(Record) + n * 24 +
         static_cast<std::size_t>(triangles_.rows()) * (12 + 24 + 24) +
         adjacency_.triangles.size() * 4 + n * 24;
}

Points3 datasetPositions(const MultiLevelTetMesh& mesh, int level, const Points3& given,
                         const std::string& sourceName) {
  if (given.rows() == mesh.nodes.rows()) return given;
  const LevelRange& r = mesh.levels.at(static_cast<std::size_t>(level));
  if (given.rows() != r.nodeCount)
    throw Error(sourceName, 0,
                "has " + std::to_string(given.rows()) + " positions; expected all " +
                    std::to_string(mesh.nodes.rows()) + " dataset nodes or the " +
                    std::to_string(r.nodeCount) + " nodes of level " + std::to_string(level));
  Points3 all = mesh.nodes;
  all.middleRows(r.firstNode, r.nodeCount) = given;
  return all;
}

}  // namespace tetskin
