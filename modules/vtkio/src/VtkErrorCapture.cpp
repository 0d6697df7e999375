// SPDX-License-Identifier: AGPL-3.0-or-later
#include "tetskin/vtkio/VtkErrorCapture.h"

#include <vtkCallbackCommand.h>
#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkStringOutputWindow.h>

namespace tetskin {
namespace {

// VTK messages read "ERROR: In <file>, line N\n<class> (<address>): text";
// keep the text.
std::string plainText(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (const auto nl = text.rfind('\n'); nl != std::string::npos) text = text.substr(nl + 1);
  if (const auto colon = text.find("): "); colon != std::string::npos)
    text = text.substr(colon + 3);
  return text;
}

void onError(vtkObject*, unsigned long, void* clientData, void* callData) {
  auto* message = static_cast<std::string*>(clientData);
  if (message->empty())
    *message = plainText(callData ? static_cast<const char*>(callData) : "unknown VTK error");
}

}  // namespace

VtkErrorCapture::VtkErrorCapture(vtkObject* source) : source_(source) {
  auto callback = vtkSmartPointer<vtkCallbackCommand>::New();
  callback->SetCallback(onError);
  callback->SetClientData(&message_);
  tag_ = source_->AddObserver(vtkCommand::ErrorEvent, callback);
  previousWindow_ = vtkOutputWindow::GetInstance();
  window_ = vtkSmartPointer<vtkStringOutputWindow>::New();
  vtkOutputWindow::SetInstance(window_);
  // VTK also logs every error through loguru to stderr; the message reaches
  // the user once, as a tetskin::Error.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkErrorCapture::~VtkErrorCapture() {
  source_->RemoveObserver(tag_);
  vtkOutputWindow::SetInstance(previousWindow_);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_INFO);
}

std::string VtkErrorCapture::message(const std::string& fallback) const {
  if (!message_.empty()) return message_;
  std::string printed = window_->GetOutput();
  // VTK's macros open with a line "Warning: In <file>, line N" (or "ERROR: ..."):
  // the text is on the next.
  if (const auto nl = printed.find('\n'); nl != std::string::npos && printed.find(": In ") < nl)
    printed = printed.substr(nl + 1);
  if (const auto nl = printed.find('\n', printed.find(": ")); nl != std::string::npos)
    printed = printed.substr(0, nl);
  printed = plainText(printed);
  return printed.empty() ? fallback : printed;
}

}  // namespace tetskin
