// SPDX-License-Identifier: AGPL-3.0-or-later
#include "vtkTetSkinGpu2PassMapper.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLBufferObject.h>
#include <vtkOpenGLHelper.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLVertexBufferObject.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <string>

#include "GpuContract.h"
#include "tetskin/shaders/Shaders.h"

vtkStandardNewMacro(vtkTetSkinGpu2PassMapper)

namespace {
// A raw OpenGL shader-storage buffer (VTK 9.1 has no wrapper for them).
struct StorageBuffer {
  GLuint id = 0;
  void upload(const void* data, std::size_t bytes) {
    if (!id) glGenBuffers(1, &id);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, id);
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_DYNAMIC_DRAW);
  }
  void release() {
    if (id) glDeleteBuffers(1, &id);
    id = 0;
  }
};

GLuint compileCompute(const std::string& code, std::string& log) {
  const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
  const char* source = code.c_str();
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char text[4096];
    glGetShaderInfoLog(shader, sizeof text, nullptr, text);
    log = text;
    glDeleteShader(shader);
    return 0;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader);
  glLinkProgram(program);
  glDeleteShader(shader);
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char text[4096];
    glGetProgramInfoLog(program, sizeof text, nullptr, text);
    log = text;
    glDeleteProgram(program);
    return 0;
  }
  return program;
}

}  // namespace

struct vtkTetSkinGpu2PassMapper::GpuState {
  StorageBuffer control, previousControl, ids, weights, shifts, triangles, faces, offsets, ring;
  vtkNew<vtkOpenGLBufferObject> previous;
  vtkNew<vtkTextureObject> previousTexture;
  GLsizeiptr previousBytes = 0;
  GLuint positions = 0, faceNormals = 0, vertexNormals = 0;  // programs
};

vtkTetSkinGpu2PassMapper::vtkTetSkinGpu2PassMapper()
    : vtkTetSkinBufferMapper(tetskin::shaders::kGpu2passDrawDeclarationsVs,
                             tetskin::shaders::kGpu2passDrawImplVs, "tetskinDeformedPositions",
                             "tetskinDeformedNormals"),
      Gpu(new GpuState) {}

vtkTetSkinGpu2PassMapper::~vtkTetSkinGpu2PassMapper() {
  delete this->Gpu;
}

void vtkTetSkinGpu2PassMapper::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Vertices: " << this->Vertices << ", ControlNodes: " << this->Nodes << "\n";
}

void vtkTetSkinGpu2PassMapper::SetSurface(const std::vector<int>& controlIds,
                                          const std::vector<float>& weights,
                                          const std::vector<float>& shifts,
                                          const std::vector<int>& triangles,
                                          const std::vector<int>& ringOffsets,
                                          const std::vector<int>& ringFaces) {
  this->Vertices = static_cast<vtkIdType>(controlIds.size() / 4);
  this->TriangleCount = static_cast<vtkIdType>(triangles.size() / 3);
  this->Ids = controlIds;
  this->Triangles.assign(static_cast<std::size_t>(4 * this->TriangleCount), 0);
  for (vtkIdType t = 0; t < this->TriangleCount; ++t)
    for (int k = 0; k < 3; ++k)
      this->Triangles[static_cast<std::size_t>(4 * t + k)] =
          triangles[static_cast<std::size_t>(3 * t + k)];
  this->Weights = weights;
  this->Shifts = shifts;
  this->RingOffsets = ringOffsets;
  this->RingFaces = ringFaces;
  if (this->RingFaces.empty()) this->RingFaces.push_back(0);  // no empty SSBOs
  this->SurfaceChanged = true;
  this->Modified();
}

void vtkTetSkinGpu2PassMapper::SetControlPositions(const float* positions, vtkIdType nodes) {
  // The state before this one (the same on the first call): dynamic fur's velocities.
  const bool first = this->Control.empty() || this->Nodes != nodes;
  this->Nodes = nodes;
  if (!first) this->PreviousControl.swap(this->Control);
  this->Control.assign(static_cast<std::size_t>(4 * nodes), 0.0f);
  for (vtkIdType v = 0; v < nodes; ++v)
    for (int k = 0; k < 3; ++k)
      this->Control[static_cast<std::size_t>(4 * v + k)] = positions[3 * v + k];
  if (first) this->PreviousControl = this->Control;
  this->ControlChanged = true;
  this->Modified();
}

void vtkTetSkinGpu2PassMapper::PrepareBuffers(vtkOpenGLRenderWindow* window) {
  GpuState& g = *this->Gpu;
  if (!this->GetGpuProblem().empty() || this->Vertices == 0) return;
  if (!g.positions) {
    std::string log;
    g.positions =
        compileCompute(tetskin::gpu::withSlots(tetskin::shaders::kGpu2passPositionsCs), log);
    if (g.positions)
      g.faceNormals =
          compileCompute(tetskin::gpu::withSlots(tetskin::shaders::kGpu2passFaceNormalsCs), log);
    if (g.faceNormals)
      g.vertexNormals =
          compileCompute(tetskin::gpu::withSlots(tetskin::shaders::kGpu2passVertexNormalsCs), log);
    if (!g.vertexNormals) {
      this->ReportGpuProblem("gpu-2pass: the compute shaders failed (OpenGL 4.3 needed): " + log);
      return;
    }
  }
  if (this->SurfaceChanged) {
    g.ids.upload(this->Ids.data(), this->Ids.size() * sizeof(int));
    g.weights.upload(this->Weights.data(), this->Weights.size() * sizeof(float));
    g.shifts.upload(this->Shifts.data(), this->Shifts.size() * sizeof(float));
    g.triangles.upload(this->Triangles.data(), this->Triangles.size() * sizeof(int));
    g.offsets.upload(this->RingOffsets.data(), this->RingOffsets.size() * sizeof(int));
    g.ring.upload(this->RingFaces.data(), this->RingFaces.size() * sizeof(int));
    std::vector<float> zeros(
        static_cast<std::size_t>(4 * std::max<vtkIdType>(this->TriangleCount, 1)), 0.0f);
    g.faces.upload(zeros.data(), zeros.size() * sizeof(float));
    zeros.assign(static_cast<std::size_t>(4 * this->Vertices), 0.0f);
    // The outputs are texture buffers for the draw pass and storage buffers here.
    const std::string vertices = std::to_string(this->Vertices) + " surface vertices";
    if (!this->UploadTexels(0, zeros, [&] { return "gpu-2pass: the positions of " + vertices; }) ||
        !this->UploadTexels(1, zeros, [&] { return "gpu-2pass: the normals of " + vertices; }))
      return;
    this->SurfaceChanged = false;
  }
  const bool newFrame = this->ControlChanged;
  if (this->ControlChanged) {
    g.control.upload(this->Control.data(), this->Control.size() * sizeof(float));
    this->ControlChanged = false;
  }
  if (this->KeepPrevious && newFrame) this->ComputePreviousPositions(window);
  const GLuint groups = static_cast<GLuint>((this->Vertices + 63) / 64);
  const GLuint faceGroups = static_cast<GLuint>((this->TriangleCount + 63) / 64);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::ControlPositions), g.control.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::BindingIds),
                   g.ids.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::BindingWeights), g.weights.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::DeformedPositions),
                   static_cast<GLuint>(this->Buffer(0)->GetHandle()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::Triangles),
                   g.triangles.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::FaceNormals),
                   g.faces.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::RingOffsets),
                   g.offsets.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::RingFaces),
                   g.ring.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::DeformedNormals),
                   static_cast<GLuint>(this->Buffer(1)->GetHandle()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::BindingShifts),
                   g.shifts.id);
  glUseProgram(g.positions);
  glUniform1i(glGetUniformLocation(g.positions, "vertexCount"), static_cast<GLint>(this->Vertices));
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(g.faceNormals);
  glUniform1i(glGetUniformLocation(g.faceNormals, "triangleCount"),
              static_cast<GLint>(this->TriangleCount));
  if (faceGroups > 0) glDispatchCompute(faceGroups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  glUseProgram(g.vertexNormals);
  glUniform1i(glGetUniformLocation(g.vertexNormals, "vertexCount"),
              static_cast<GLint>(this->Vertices));
  glDispatchCompute(groups, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                  GL_BUFFER_UPDATE_BARRIER_BIT);
  glUseProgram(0);
  // VTK caches the bound program; make it rebind after our glUseProgram.
  window->GetShaderCache()->ReleaseCurrentShader();
}

void vtkTetSkinGpu2PassMapper::ComputePreviousPositions(vtkOpenGLRenderWindow* window) {
  GpuState& g = *this->Gpu;
  const auto bytes = static_cast<GLsizeiptr>(4 * this->Vertices * sizeof(float));
  if (!g.previous->GetHandle() || g.previousBytes != bytes) {
    g.previous->Upload(std::vector<float>(static_cast<std::size_t>(4 * this->Vertices), 0.0f),
                       vtkOpenGLBufferObject::TextureBuffer);
    g.previousBytes = bytes;
    g.previousTexture->SetContext(window);
    g.previousTexture->CreateTextureBuffer(static_cast<unsigned int>(this->Vertices), 4, VTK_FLOAT,
                                           g.previous);
  }
  // The positions pass again, over the previous control state.
  g.previousControl.upload(this->PreviousControl.data(),
                           this->PreviousControl.size() * sizeof(float));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::ControlPositions), g.previousControl.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::BindingIds),
                   g.ids.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::BindingWeights), g.weights.id);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER,
                   tetskin::gpu::index(tetskin::gpu::Slot::DeformedPositions),
                   static_cast<GLuint>(g.previous->GetHandle()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tetskin::gpu::index(tetskin::gpu::Slot::BindingShifts),
                   g.shifts.id);
  glUseProgram(g.positions);
  glUniform1i(glGetUniformLocation(g.positions, "vertexCount"), static_cast<GLint>(this->Vertices));
  glDispatchCompute(static_cast<GLuint>((this->Vertices + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void vtkTetSkinGpu2PassMapper::SetKeepPreviousPositions(bool keep) {
  this->KeepPrevious = keep;
}
vtkTextureObject* vtkTetSkinGpu2PassMapper::DeformedPositions() {
  return this->Texture(0);
}
vtkTextureObject* vtkTetSkinGpu2PassMapper::DeformedNormals() {
  return this->Texture(1);
}
vtkTextureObject* vtkTetSkinGpu2PassMapper::PreviousPositions() {
  return this->Gpu->previousTexture;
}

std::vector<float> vtkTetSkinGpu2PassMapper::ReadDeformedPositions(vtkRenderWindow* window) {
  std::vector<float> out(static_cast<std::size_t>(4 * this->Vertices));
  if (out.empty() || !this->Buffer(0)->GetHandle()) return out;
  window->MakeCurrent();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(this->Buffer(0)->GetHandle()));
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                     static_cast<GLsizeiptr>(out.size() * sizeof(float)), out.data());
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  const double* origin = this->GetModelOrigin();  // (the GPU's are measured from it)
  for (std::size_t v = 0; v < out.size() / 4; ++v)
    for (std::size_t k = 0; k < 3; ++k)
      out[4 * v + k] = static_cast<float>(out[4 * v + k] + origin[k]);
  return out;
}

void vtkTetSkinGpu2PassMapper::ReleaseGraphicsResources(vtkWindow* window) {
  GpuState& g = *this->Gpu;
  for (StorageBuffer* b : {&g.control, &g.previousControl, &g.ids, &g.weights, &g.shifts,
                           &g.triangles, &g.faces, &g.offsets, &g.ring})
    b->release();
  for (GLuint* p : {&g.positions, &g.faceNormals, &g.vertexNormals}) {
    if (*p) glDeleteProgram(*p);
    *p = 0;
  }
  g.previousTexture->ReleaseGraphicsResources(window);
  g.previous->ReleaseGraphicsResources();
  g.previousBytes = 0;
  this->SurfaceChanged = this->ControlChanged = true;
  this->Superclass::ReleaseGraphicsResources(window);
}
