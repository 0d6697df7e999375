// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// An offscreen render window for `tetskin render`, tests and benchmarks:
// needs an X display (Debian's VTK is built for X only; use xvfb-run).

#include <vtkSmartPointer.h>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "tetskin/core/OptionSchema.h"
#include "tetskin/core/UpAxis.h"

class vtkRenderer;
class vtkRenderWindow;
class vtkImageData;

namespace tetskin {

enum class CameraPreset { Front, Side, Top, Iso };
template <>
struct EnumSchema<CameraPreset> {
  static constexpr const char* what = "camera preset";
  static constexpr EnumValue<CameraPreset> values[] = {{CameraPreset::Iso, "iso", ""},
                                                       {CameraPreset::Front, "front", ""},
                                                       {CameraPreset::Side, "side", ""},
                                                       {CameraPreset::Top, "top", ""}};
};
inline constexpr EnumOption<CameraPreset> kCameraOption{"camera", "--camera", "the camera"};
// The preset `render` and the GUI's View dock start with.
inline constexpr CameraPreset kDefaultCamera = CameraPreset::Iso;
// Looks at `bounds` (xmin, xmax, ...) from the preset direction, y up.
void placeCamera(vtkRenderer* renderer, CameraPreset preset, const double bounds[6],
                 UpAxis up = UpAxis::Y);
// Whether all eight corners of `bounds` lie in the renderer's view (its
// active camera, its viewport's aspect).
bool boundsInView(vtkRenderer* renderer, const double bounds[6]);
// TetSkin's gradient background (every view looks alike).
void styleBackground(vtkRenderer* renderer);

class OffscreenView {
 public:
  // Throws Error when there is no X display to connect to (XDisplay.h).
  OffscreenView(int width, int height);
  ~OffscreenView();
  vtkRenderer* renderer() const;
  vtkRenderWindow* window() const;
  // Looks at `bounds` (xmin, xmax, ...) from the preset direction, y up.
  void setCamera(CameraPreset preset, const double bounds[6], UpAxis up = UpAxis::Y);
  void render();
  vtkSmartPointer<vtkImageData> capture();
  void writePng(const std::filesystem::path& path);  // atomic
  // The OpenGL renderer string (e.g. "llvmpipe (LLVM 15.0.6, 256 bits)").
  std::string glRenderer();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tetskin
