// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the C++ side of the GPU render paths and their shaders (shaders/)
// agree on, in one place: the shader storage buffer slots of gpu-2pass's
// compute passes and the vertex attributes the mappers feed the vertex
// shaders. The slots reach the GLSL as #defines (withSlots(), inserted
// after a shader's #version line), so a shader names a slot, never its
// number; rendering.gpu_contract (tests/rendering) checks that every
// shader's buffers name a slot defined here and that every attribute here
// is declared by a shader, as `in TYPE NAME;`.

#include <array>
#include <string>
#include <string_view>

namespace tetskin::gpu {

// The buffers of gpu-2pass (vtkTetSkinGpu2PassMapper), by binding point.
enum class Slot : unsigned {
  ControlPositions = 0,   // vec4 per control node (the frame's positions)
  BindingIds = 1,         // ivec4 per surface vertex (4th -1: a triangle)
  BindingWeights = 2,     // vec4 per surface vertex
  DeformedPositions = 3,  // vec4 per surface vertex (the draw's position buffer)
  Triangles = 4,          // ivec4 per triangle
  FaceNormals = 5,        // vec4 per triangle
  RingOffsets = 6,        // int per surface vertex + 1: where its ring starts
  RingFaces = 7,          // int per ring entry: the triangles around a vertex
  DeformedNormals = 8,    // vec4 per surface vertex (the draw's normal buffer)
  BindingShifts = 9,      // vec4 per surface vertex: the shift x y z and the offset d
};

struct SlotName {
  Slot slot;
  const char* define;  // the GLSL macro naming it
};
inline constexpr std::array<SlotName, 10> kSlots{{
    {Slot::ControlPositions, "TETSKIN_SLOT_CONTROL_POSITIONS"},
    {Slot::BindingIds, "TETSKIN_SLOT_BINDING_IDS"},
    {Slot::BindingWeights, "TETSKIN_SLOT_BINDING_WEIGHTS"},
    {Slot::DeformedPositions, "TETSKIN_SLOT_DEFORMED_POSITIONS"},
    {Slot::Triangles, "TETSKIN_SLOT_TRIANGLES"},
    {Slot::FaceNormals, "TETSKIN_SLOT_FACE_NORMALS"},
    {Slot::RingOffsets, "TETSKIN_SLOT_RING_OFFSETS"},
    {Slot::RingFaces, "TETSKIN_SLOT_RING_FACES"},
    {Slot::DeformedNormals, "TETSKIN_SLOT_DEFORMED_NORMALS"},
    {Slot::BindingShifts, "TETSKIN_SLOT_BINDING_SHIFTS"},
}};

constexpr unsigned index(Slot slot) {
  return static_cast<unsigned>(slot);
}

// `source` (a shader whose first line is its #version) with the slots'
// #defines after that line.
std::string withSlots(std::string_view source);

// The vertex attributes the mappers map VTK point arrays to.
namespace attribute {
inline constexpr const char* kControlIds = "tetskinControlIds";  // gpu-1pass: 3 or 4 node ids
inline constexpr const char* kWeights = "tetskinWeights";        // gpu-1pass: their weights
inline constexpr const char* kShift = "tetskinShift";            // gpu-1pass: shift x y z, offset d
inline constexpr const char* kRestNormal = "tetskinRestNormal";  // gpu-1pass embed
inline constexpr const char* kFurTCoords = "tetskinFurTCoords";  // fur: the fur texture's coords
inline constexpr const char* kFurHeight = "tetskinFurHeight";    // fur: the shell's height
inline constexpr const char* kColorTCoords = "tetskinColorTCoords";  // fur: the colour texture's
inline constexpr const char* kFurSource = "tetskinFurSource";        // gpu fur: the unsplit vertex
inline constexpr std::array<const char*, 8> kAll{
    kControlIds, kWeights, kShift, kRestNormal, kFurTCoords, kFurHeight, kColorTCoords, kFurSource};
}  // namespace attribute

}  // namespace tetskin::gpu
