// SPDX-License-Identifier: AGPL-3.0-or-later
#include "ViewCapture.h"

#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <QImage>
#include <QPainter>
#include <QPixmap>
#include <QWidget>

#include "tetskin/core/Error.h"
#include "tetskin/io/AtomicFile.h"
#include "tetskin/io/FileNames.h"
#include "tetskin/vtkio/VtkFiles.h"

namespace tetskin::gui {

vtkSmartPointer<vtkImageData> grabViewImage(vtkRenderWindow* window) {
  auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

QString screenshotNameProblem(const QString& path) {
  // The image is a PNG whatever the name says; a name that says otherwise
  // would mislead whoever opens it.
  if (lowerExtension(path.toStdString()) == ".png") return {};
  return "a screenshot is a PNG image: the name must end in .png";
}

void writeScreenshot(const std::filesystem::path& path, vtkImageData* view, QWidget* window,
                     const QWidget* viewWidget) {
  if (const QString problem = screenshotNameProblem(QString::fromStdString(path.string()));
      !problem.isEmpty())
    throw Error(path.string(), 0, problem.toStdString());
  if (!window) {
    writePng(path, view);
    return;
  }
  // Qt grabs the widgets but not the OpenGL view: paint VTK's own image of
  // it into place.
  int dims[3];
  view->GetDimensions(dims);
  const int channels = view->GetNumberOfScalarComponents();
  QImage picture(dims[0], dims[1], QImage::Format_RGB888);
  const auto* pixels = static_cast<const unsigned char*>(view->GetScalarPointer());
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const unsigned char* p = pixels + channels * (y * dims[0] + x);
      picture.setPixel(x, dims[1] - 1 - y, qRgb(p[0], p[1], p[2]));
    }
  QPixmap whole = window->grab();
  QPainter painter(&whole);
  painter.drawImage(QRect(viewWidget->mapTo(window, QPoint(0, 0)), viewWidget->size()), picture);
  painter.end();
  writeFileAtomically(path, [&](const std::filesystem::path& tmp) {
    if (!whole.save(QString::fromStdString(tmp.string()), "PNG"))
      throw Error(path.string(), 0, "cannot write the PNG image");
  });
}

}  // namespace tetskin::gui
