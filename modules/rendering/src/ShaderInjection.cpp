// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ShaderInjection.h"

#include <vtkShaderProgram.h>

#include <string>

namespace tetskin::detail {

void insertVertexCode(vtkShader* vertexShader, const char* declarations,
                      const char* implementation) {
  std::string vs = vertexShader->GetSource();
  vtkShaderProgram::Substitute(vs, "//VTK::CustomUniforms::Dec", declarations);
  vtkShaderProgram::Substitute(vs, "//VTK::CustomBegin::Impl", implementation);
  vertexShader->SetSource(vs);
}

void useDeformedVertex(vtkShader* vertexShader) {
  std::string vs = vertexShader->GetSource();
  vtkShaderProgram::Substitute(vs, "* vertexMC", "* deformedMC", true);
  vtkShaderProgram::Substitute(vs, "normalMatrix * normalMC", "normalMatrix * deformedNormalMC",
                               true);
  vertexShader->SetSource(vs);
}

}  // namespace tetskin::detail
