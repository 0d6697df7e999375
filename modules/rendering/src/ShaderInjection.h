// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How TetSkin's mappers put their code into VTK's polydata shaders: GLSL
// inserted before VTK's own at //VTK::CustomUniforms::Dec and
// //VTK::CustomBegin::Impl, and, once VTK has substituted its code, every
// `* vertexMC` and the normal transform redirected to the shader's
// `deformedMC` and `deformedNormalMC`.

#include <vtkShader.h>

namespace tetskin::detail {

void insertVertexCode(vtkShader* vertexShader, const char* declarations,
                      const char* implementation);
void useDeformedVertex(vtkShader* vertexShader);

}  // namespace tetskin::detail
