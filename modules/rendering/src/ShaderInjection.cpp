// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ShaderInjection.h"

#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkOpenGLActor.h>
#include <vtkOpenGLCamera.h>
#include <vtkRenderer.h>
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

void useModelOrigin(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor,
                    const double origin[3]) {
  if (!program || (origin[0] == 0 && origin[1] == 0 && origin[2] == 0)) return;
  vtkMatrix4x4 *wcvc, *vcdc, *wcdc;
  vtkMatrix3x3* norms;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
      ->GetKeyMatrices(ren, wcvc, norms, vcdc, wcdc);
  // VTK's key matrices act on row vectors: the translation is the bottom row.
  vtkNew<vtkMatrix4x4> toModel;
  for (int k = 0; k < 3; ++k) toModel->SetElement(3, k, origin[k]);
  if (!actor->GetIsIdentity()) {
    vtkMatrix4x4* mcwc;
    vtkMatrix3x3* actorNormals;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(mcwc, actorNormals);
    vtkMatrix4x4::Multiply4x4(toModel, mcwc, toModel);
  }
  vtkNew<vtkMatrix4x4> product;
  vtkMatrix4x4::Multiply4x4(toModel, wcdc, product);
  program->SetUniformMatrix("MCDCMatrix", product);
  if (program->IsUniformUsed("MCVCMatrix")) {
    vtkMatrix4x4::Multiply4x4(toModel, wcvc, product);
    program->SetUniformMatrix("MCVCMatrix", product);
  }
}

}  // namespace tetskin::detail
