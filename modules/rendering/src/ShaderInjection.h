// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// How TetSkin's mappers put their code into VTK's polydata shaders: GLSL
// inserted before VTK's own at //VTK::CustomUniforms::Dec and
// //VTK::CustomBegin::Impl, and, once VTK has substituted its code, every
// `* vertexMC` and the normal transform redirected to the shader's
// `deformedMC` and `deformedNormalMC`.

#include <vtkShader.h>

class vtkActor;
class vtkRenderer;
class vtkShaderProgram;

namespace tetskin::detail {

void insertVertexCode(vtkShader* vertexShader, const char* declarations,
                      const char* implementation);
void useDeformedVertex(vtkShader* vertexShader);

// For a mapper whose shader computes positions relative to `origin` (the
// model coordinates minus it): re-sets VTK's MCDC and MCVC matrices with a
// translation by `origin` first, multiplied in double on the CPU, as VTK
// does for its own shifted coordinates (vtkOpenGLPolyDataMapper::
// SetCameraShaderParameters). The GPU then never holds a large coordinate:
// single precision keeps about 7 digits, so a model 1e6 away from the
// origin was drawn jagged. Nothing for an origin of 0 or no program.
void useModelOrigin(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor,
                    const double origin[3]);

}  // namespace tetskin::detail
