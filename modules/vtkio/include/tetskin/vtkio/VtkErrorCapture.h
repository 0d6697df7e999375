// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Collects what a VTK algorithm or parser reports (its error events, and
// whatever VTK prints through the output window meanwhile: executive errors,
// parser messages) instead of printing it, so a failed read or write becomes
// one tetskin::Error naming the file (and, in tests, so an algorithm's
// reported error can be checked). Not thread-safe: VTK's output window is
// global.

#include <vtkSmartPointer.h>

#include <string>

class vtkObject;
class vtkOutputWindow;
class vtkStringOutputWindow;

namespace tetskin {

class VtkErrorCapture {
 public:
  explicit VtkErrorCapture(vtkObject* source);
  ~VtkErrorCapture();
  VtkErrorCapture(const VtkErrorCapture&) = delete;
  VtkErrorCapture& operator=(const VtkErrorCapture&) = delete;

  // The source raised an error event.
  bool failed() const { return !message_.empty(); }
  // The first error, or else the first message VTK printed (a warning), or `fallback`.
  std::string message(const std::string& fallback = "VTK reported an error") const;

 private:
  vtkObject* source_;
  unsigned long tag_ = 0;
  std::string message_;
  vtkSmartPointer<vtkOutputWindow> previousWindow_;
  vtkSmartPointer<vtkStringOutputWindow> window_;
};

}  // namespace tetskin
