// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Pictures of the window: the 3D view's image as VTK draws it, and
// screenshots (PNG) of the view alone or of the whole window with its
// docks. Qt's own grab of an OpenGL view comes out black under Xvfb, so
// the view is always read back through VTK (doc/dev/platform-notes.md).

#include <vtkSmartPointer.h>

#include <QString>
#include <filesystem>

class QWidget;
class vtkImageData;
class vtkRenderWindow;

namespace tetskin::gui {

// `window`'s image (its back buffer), drawn by the caller just before.
vtkSmartPointer<vtkImageData> grabViewImage(vtkRenderWindow* window);

// Why `path` cannot name a screenshot (the image is a PNG: the name must
// end in .png), or an empty string.
QString screenshotNameProblem(const QString& path);

// Writes `view` (grabViewImage's) as a PNG at `path`, atomically; with
// `window` given, the window's widgets with `view` painted in the place of
// `viewWidget`. Throws Error naming the file.
void writeScreenshot(const std::filesystem::path& path, vtkImageData* view,
                     QWidget* window = nullptr, const QWidget* viewWidget = nullptr);

}  // namespace tetskin::gui
