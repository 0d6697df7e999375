// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Draws fur geometry (shells or fins, see tetskin/fur/FurGeometry.h) with the
// fur shading of the report's section 5, as shader replacements of VTK's
// polydata mapper: a 3D fur texture (s, t, height) gives every shell its
// layer; a colour texture over the surface's own coordinates tints the fur
// and masks it (alpha 0: no fur); specular light is scaled by the hair's
// alpha and pushed off the mirror direction (velvet) or computed along the
// hairs (Kajiya-Kay). This class draws geometry the CPU placed (fur-cpu):
// the input's points, normals and point arrays FurTCoords (2), FurHeight (1)
// and ColorTCoords (2). Put it on a translucent actor drawn after the skin.

#include <vtkNew.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkSmartPointer.h>

#include <array>
#include <cstdint>
#include <vector>

class vtkImageData;
class vtkTextureObject;

class vtkTetSkinFurMapper : public vtkOpenGLPolyDataMapper {
 public:
  static vtkTetSkinFurMapper* New();
  vtkTypeMacro(vtkTetSkinFurMapper, vtkOpenGLPolyDataMapper)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Where the positions the shader computes are measured from: the GPU
  // paths give the control nodes' positions minus it, so that a model far
  // from the origin keeps its precision in single precision (0: none).
  void SetModelOrigin(const double origin[3]);
  const double* GetModelOrigin() const { return this->ModelOrigin; }

  // RGBA, layer-major (tetskin::FurTexture::rgba).
  void SetFurTexture(int size, int layers, const std::vector<std::uint8_t>& rgba);
  // RGB or RGBA unsigned char image; nullptr for none.
  void SetColorTexture(vtkImageData* image);
  void SetFins(bool fins);
  void SetKajiyaKay(bool kajiyaKay);
  void SetVelvet(double velvet);
  void SetTint(const std::array<double, 3>& rgb);

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  // How many pixels tall fur of `length` model units appears around the
  // centre of `bounds` in `ren`'s camera (for the adaptive shell count).
  static double FurPixelHeight(vtkRenderer* ren, const double bounds[6], double length);

 protected:
  vtkTetSkinFurMapper();
  ~vtkTetSkinFurMapper() override;
  // The vertex stage: where the fur vertex comes from (fur-cpu: the input points).
  virtual const char* VertexDeclarations() const;
  virtual const char* VertexImplementation() const;
  void ReplaceShaderValues(std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren,
                           vtkActor* act) override;
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

 private:
  vtkTetSkinFurMapper(const vtkTetSkinFurMapper&) = delete;
  void operator=(const vtkTetSkinFurMapper&) = delete;
  vtkNew<vtkTextureObject> FurTexture, ColorTexture;
  std::vector<std::uint8_t> FurTexels;
  int FurSize = 0, FurLayers = 0;
  vtkSmartPointer<vtkImageData> ColorImage;
  bool FurDirty = false, ColorDirty = false;
  bool Fins = false, KajiyaKay = false;
  float Velvet = 0.5f;
  std::array<float, 3> Tint{1, 1, 1};
  double ModelOrigin[3] = {0, 0, 0};
};
