// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the GPU-deforming mappers share: two per-vertex or per-node texture
// buffers the vertex shader reads (named by the subclass), the shader code
// injected at //VTK::CustomUniforms::Dec and //VTK::CustomBegin::Impl, after
// which every `* vertexMC` and the normal transform use the shader's
// `deformedMC` and `deformedNormalMC`, and the deformed bounds the CPU knows.
// Subclasses fill the buffers in PrepareBuffers() (called with the context
// current, before the draw); a buffer never filled is not bound (its
// shader need not declare the sampler).

#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>

#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class vtkTetSkinBufferMapper : public vtkOpenGLPolyDataMapper {
 public:
  vtkTypeMacro(vtkTetSkinBufferMapper, vtkOpenGLPolyDataMapper)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Bounds of the deformed surface (xmin, xmax, ...); until set, the input's.
  void SetDeformedBounds(const double bounds[6]);

  void ComputeBounds() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

 protected:
  // `declarations`/`implementation`: GLSL inserted before VTK's own; the
  // sampler uniforms the two texture buffers are bound to.
  vtkTetSkinBufferMapper(const char* declarations, const char* implementation,
                         const char* firstSampler, const char* secondSampler);
  ~vtkTetSkinBufferMapper() override;
  virtual void PrepareBuffers(vtkOpenGLRenderWindow* window) = 0;
  // Other shader code than the constructor's, and the sampler of the
  // second buffer it reads (before the first render).
  void SetShaderCode(const char* declarations, const char* implementation,
                     const char* secondSampler);
  // Uploads `values` (4 floats per texel) into buffer k (0 or 1) and its texture.
  void UploadTexels(int k, const std::vector<float>& values);
  vtkOpenGLBufferObject* Buffer(int k);
  vtkTextureObject* Texture(int k);

  void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                           vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

 private:
  vtkTetSkinBufferMapper(const vtkTetSkinBufferMapper&) = delete;
  void operator=(const vtkTetSkinBufferMapper&) = delete;
  const char* Declarations;
  const char* Implementation;
  const char* Samplers[2];
  double DeformedBounds[6] = {0, -1, 0, -1, 0, -1};
  vtkNew<vtkOpenGLBufferObject> Buffers[2];
  vtkNew<vtkTextureObject> Textures[2];
};
