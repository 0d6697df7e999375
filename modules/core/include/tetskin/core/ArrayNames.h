// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// The names of the arrays TetSkin's files carry (doc/user/file-formats.md), in one
// place: the writers, the readers, the VTK filters, the mappers and the
// front ends all name them through these, so none can drift from another.
// ParaView users, scripts and tests read them as they are here.

namespace tetskin::arrays {

// Control-mesh frames (.vtu of simulate, the GUI's Record and Export).
inline constexpr const char* kDisplacement = "Displacement";    // point vectors: position - rest
inline constexpr const char* kVelocity = "Velocity";            // point vectors
inline constexpr const char* kExternalForce = "ExternalForce";  // point vectors, N
inline constexpr const char* kReactionForce = "ReactionForce";  // point vectors, N
// Point vectors, N: what the floor and obstacles exert on a node (springs
// and the last step's friction); on a skin vertex, its contact spring.
// Control frames of a run with contact, and skin frames of a run with
// obstacles.
inline constexpr const char* kContactForce = "ContactForce";
// Skin frames of a run with obstacles, point scalars: the signed distance
// (model units) into the obstacle a vertex is deepest in, positive inside;
// -r for a vertex farther than the contact search radius r from all.
inline constexpr const char* kPenetration = "Penetration";
inline constexpr const char* kPrescribed = "Prescribed";          // point 0/1: held or driven
inline constexpr const char* kVonMisesStress = "VonMisesStress";  // cell scalars, Pa
// Cell tensors of six components (xx, yy, zz, xy, yz, xz, as VTK orders a
// symmetric tensor), Pa: the stress in the world's axes.
inline constexpr const char* kStress = "Stress";
// Cell scalars: the von Mises equivalent strain (CorotatedFem::elementMeasures).
inline constexpr const char* kEquivalentStrain = "EquivalentStrain";
inline constexpr const char* kLevel = "Level";  // cell data of a level, field data of a binding

// Bindings (.vtp of bind): per surface vertex.
inline constexpr const char* kControlIds = "ControlIds";  // 3 (or 4: embed) node ids
inline constexpr const char* kWeights = "Weights";        // barycentric weights, sum 1
inline constexpr const char* kDistance = "Distance";
inline constexpr const char* kMinBarycentric = "MinBarycentric";
inline constexpr const char* kFaceId = "FaceId";  // the element bound to (SurfaceBinding.h)

// Surfaces: the active point normals.
inline constexpr const char* kNormals = "Normals";
// Surface frames (simulate --surface, compare): VonMisesStress and
// EquivalentStrain as point scalars, carried from the control elements
// (SurfaceFields.h); and compare's errors against the reference level, per
// vertex: the distance (model units), the same over the rest surface's
// bounding-box diagonal, and the angle between the normals (degrees).
inline constexpr const char* kSurfaceError = "SurfaceError";
inline constexpr const char* kRelativeError = "RelativeError";
inline constexpr const char* kNormalAngle = "NormalAngle";

}  // namespace tetskin::arrays
