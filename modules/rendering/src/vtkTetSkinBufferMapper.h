// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// What the GPU-deforming mappers share: two per-vertex or per-node texture
// buffers the vertex shader reads (named by the subclass), the shader code
// injected at //VTK::CustomUniforms::Dec and //VTK::CustomBegin::Impl, after
// which every `* vertexMC` and the normal transform use the shader's
// `deformedMC` and `deformedNormalMC`, and the deformed bounds the CPU knows.
// Subclasses fill the buffers in PrepareBuffers() (called with the context
// current, before the draw); a buffer never filled is not bound (its
// shader need not declare the sampler). What the GPU cannot do (a texture
// buffer longer than the OpenGL allows, compute shaders it cannot compile)
// is reported once, through GetGpuProblem() and a VTK error, and the
// surface is then not drawn rather than drawn from unfilled buffers.

#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>

#include <functional>
#include <string>
#include <vector>

class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class vtkTetSkinBufferMapper : public vtkOpenGLPolyDataMapper {
 public:
  vtkTypeMacro(vtkTetSkinBufferMapper, vtkOpenGLPolyDataMapper)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Where the positions the shader computes are measured from: the GPU
  // paths give the control nodes' positions minus it, so that a model far
  // from the origin keeps its precision in single precision (0: none).
  void SetModelOrigin(const double origin[3]);
  const double* GetModelOrigin() const { return this->ModelOrigin; }

  // Bounds of the deformed surface (xmin, xmax, ...); until set, the input's.
  void SetDeformedBounds(const double bounds[6]);

  // Why this mapper cannot draw its surface on this OpenGL, or empty; set
  // by the render that found it and kept (the surface does not change).
  const std::string& GetGpuProblem() const { return this->GpuProblem; }
  // Caps the texels of one texture buffer below the OpenGL's own
  // GL_MAX_TEXTURE_BUFFER_SIZE (0, the default: that limit alone): to try a
  // model against a smaller GPU's limit (OpenGL 4 promises 65536) and to
  // test the refusal on an OpenGL with a larger one.
  void SetTexelLimit(vtkIdType texels);

  void ComputeBounds() override;
  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
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
  // Uploads `values` (4 floats per texel) into buffer k (0 or 1) and its
  // texture; when they are more texels than the OpenGL allows, nothing is
  // uploaded, false returned and `what()` names them in the message (built
  // only then: gpu-1pass uploads every frame).
  bool UploadTexels(int k, const std::vector<float>& values,
                    const std::function<std::string()>& what);
  // Records `problem` (the first one only) and reports it as a VTK error.
  void ReportGpuProblem(const std::string& problem);
  vtkOpenGLBufferObject* Buffer(int k);
  vtkTextureObject* Texture(int k);

  void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                           vtkActor* act) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

 private:
  vtkTetSkinBufferMapper(const vtkTetSkinBufferMapper&) = delete;
  void operator=(const vtkTetSkinBufferMapper&) = delete;
  const char* Declarations;
  const char* Implementation;
  const char* Samplers[2];
  double DeformedBounds[6] = {0, -1, 0, -1, 0, -1};
  std::string GpuProblem;
  vtkIdType TexelLimit = 0;
  vtkIdType GLTexelLimit = 0;  // GL_MAX_TEXTURE_BUFFER_SIZE, queried once per context
  vtkNew<vtkOpenGLBufferObject> Buffers[2];
  vtkNew<vtkTextureObject> Textures[2];
  double ModelOrigin[3] = {0, 0, 0};
};
