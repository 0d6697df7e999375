// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How each vertex of a high-resolution surface is tied to the control mesh
// (report section 3): the plain-data interface between binding (which makes
// it) and deformation (which applies it every frame).

#include <optional>
#include <string>
#include <string_view>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/Types.h"

namespace tetskin {

enum class BindingMethod {
  Closest,  // boundary triangle at the smallest true distance (exact)
  Seed,     // the report's method: plane projection, barycentric score, 8 octants
  Embed,    // containing tetrahedron, 4 weights (SOFA/VegaFEM style)
};

enum class OffsetMode {
  // x = sum w_i X_i + d n, n the unit normal of the deformed control triangle:
  // exact at rest and under rigid motion.
  Normal,
  // x = x_rest + sum w_i (X_i - X_i,rest): the report's formula 4.1.
  Displacement,
};

struct SurfaceBinding {
  BindingMethod method = BindingMethod::Closest;
  OffsetMode offset = OffsetMode::Normal;
  int level = -1;  // dataset level the surface is bound to

  // Per surface vertex (#V rows). Control ids are in the dataset's node
  // numbering; for triangle methods the 4th id is -1 and the 4th weight 0.
  Eigen::Matrix<int, Eigen::Dynamic, 4, Eigen::RowMajor> controlIds;  // #V x 4
  Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor> weights;  // #V x 4, rows sum to 1
  // #V: signed distance to the triangle's plane (model units); for Embed the
  // distance to the nearest element (0 inside the volume).
  Eigen::VectorXd distance;
  // The element the vertex is bound to, in the dataset's numbering (as the
  // control ids), for every method: the element of its boundary face
  // (closest, seed) or the element that holds it (embed).
  Eigen::VectorXi faceId;
  Eigen::VectorXd minBarycentric;  // smallest weight: < 0 means outside the triangle

  Index vertexCount() const { return controlIds.rows(); }
  // 3 for triangle bindings, 4 for Embed.
  int controlsPerVertex() const { return method == BindingMethod::Embed ? 4 : 3; }
  void resize(Index vertices);
};

template <>
struct EnumSchema<BindingMethod> {
  static constexpr const char* what = "binding method";
  static constexpr EnumValue<BindingMethod> values[] = {
      {BindingMethod::Closest, "closest", "exact"},
      {BindingMethod::Seed, "seed", "the report's"},
      {BindingMethod::Embed, "embed", "tetrahedra"}};
};
template <>
struct EnumSchema<OffsetMode> {
  static constexpr const char* what = "offset mode";
  static constexpr EnumValue<OffsetMode> values[] = {
      {OffsetMode::Normal, "normal", "offset along the deformed triangle's normal"},
      {OffsetMode::Displacement, "displacement", "the report's formula 4.1"}};
};
// The binding's enum options (their defaults: BindingOptions').
namespace binding_option {
inline constexpr EnumOption<BindingMethod> kMethod{"method", "--method", "the binding method"};
inline constexpr EnumOption<OffsetMode> kOffset{"offset", "--offset", "the offset mode"};
}  // namespace binding_option

// Throws Error naming `name` and the vertex when sizes disagree, an id is
// outside [0, nodeCount), or weights are not finite or do not sum to 1.
void validateBinding(const SurfaceBinding& binding, Index surfaceVertices, Index nodeCount,
                     const std::string& name);

}  // namespace tetskin
