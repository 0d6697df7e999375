// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/rendering/OffscreenView.h"

#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <cmath>
#include <sstream>

#include "tetskin/core/Error.h"
#include "tetskin/rendering/XDisplay.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin {

struct OffscreenView::Impl {
  vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkRenderWindow> window = vtkSmartPointer<vtkRenderWindow>::New();
};

OffscreenView::OffscreenView(int width, int height) : impl_(std::make_unique<Impl>()) {
  // Without a display Debian's VTK aborts the process; say what to do instead.
  if (const std::string problem = xDisplayProblem(); !problem.empty())
    throw Error("rendering needs an X display: run under xvfb-run -a (" + problem + ")");
  impl_->window->SetOffScreenRendering(1);
  impl_->window->SetMultiSamples(0);  // identical images on every run
  impl_->window->SetSize(width, height);
  impl_->window->AddRenderer(impl_->renderer);
  styleBackground(impl_->renderer);
}

OffscreenView::~OffscreenView() = default;
vtkRenderer* OffscreenView::renderer() const {
  return impl_->renderer;
}
vtkRenderWindow* OffscreenView::window() const {
  return impl_->window;
}

void OffscreenView::setCamera(CameraPreset preset, const double bounds[6], UpAxis up) {
  placeCamera(impl_->renderer, preset, bounds, up);
}

void placeCamera(vtkRenderer* renderer, CameraPreset preset, const double bounds[6],
                 UpAxis upAxis) {
  vtkCamera* camera = renderer->GetActiveCamera();
  const double center[3] = {(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                            (bounds[4] + bounds[5]) / 2};
  double direction[3] = {0, 0, 1};
  double up[3] = {0, 1, 0};
  switch (preset) {
    case CameraPreset::Front:
      break;
    case CameraPreset::Side:
      direction[0] = 1, direction[2] = 0;
      break;
    case CameraPreset::Top:
      direction[1] = 1, direction[2] = 0, up[1] = 0, up[2] = -1;
      break;
    case CameraPreset::Iso:
      direction[0] = 0.6, direction[1] = 0.45, direction[2] = 0.66;
      break;
  }
  // (The presets are written for y up; a z-up model is seen as a y-up one.)
  const Eigen::Matrix3d turn = fromYUp(upAxis);
  const Eigen::Vector3d d = turn * Eigen::Vector3d(direction[0], direction[1], direction[2]);
  const Eigen::Vector3d u = turn * Eigen::Vector3d(up[0], up[1], up[2]);
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + d[0], center[1] + d[1], center[2] + d[2]);
  camera->SetViewUp(u[0], u[1], u[2]);
  renderer->ResetCamera(const_cast<double*>(bounds));
}

bool boundsInView(vtkRenderer* renderer, const double bounds[6]) {
  for (int corner = 0; corner < 8; ++corner) {
    double x = bounds[corner & 1], y = bounds[2 + ((corner >> 1) & 1)],
           z = bounds[4 + ((corner >> 2) & 1)];
    renderer->WorldToView(x, y, z);
    if (!(std::abs(x) <= 1 && std::abs(y) <= 1)) return false;
  }
  return true;
}

void styleBackground(vtkRenderer* renderer) {
  renderer->SetBackground(0.12, 0.13, 0.15);
  renderer->SetBackground2(0.32, 0.34, 0.40);
  renderer->GradientBackgroundOn();
}

void OffscreenView::render() {
  impl_->window->Render();
}

vtkSmartPointer<vtkImageData> OffscreenView::capture() {
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(impl_->window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkSmartPointer<vtkImageData> image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

void OffscreenView::writePng(const std::filesystem::path& path) {
  tetskin::writePng(path, capture());
}

std::string OffscreenView::glRenderer() {
  std::istringstream report(impl_->window->ReportCapabilities());
  std::string line;
  while (std::getline(report, line))
    if (line.rfind("OpenGL renderer string:", 0) == 0) {
      line = line.substr(line.find(':') + 1);
      return line.substr(line.find_first_not_of(' '));
    }
  return "unknown";
}

}  // namespace tetskin
