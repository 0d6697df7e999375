// SPDX-License-Identifier: AGPL-3.0-or-later
#include "RecentFiles.h"

#include <QMenu>
#include <QSettings>

namespace tetskin::gui {
namespace {
constexpr int kMaxRecent = 8;
}

RecentFiles::RecentFiles(QMenu* menu, std::function<void(const QString&)> open)
    : QObject(menu), menu_(menu), open_(std::move(open)) {
  refresh();
}

void RecentFiles::remember(const QString& path) {
  QSettings settings;
  QStringList recent = settings.value("recentFiles").toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > kMaxRecent) recent.removeLast();
  settings.setValue("recentFiles", recent);
  refresh();
}

QStringList RecentFiles::files() const {
  return QSettings().value("recentFiles").toStringList();
}

void RecentFiles::refresh() {
  menu_->clear();
  for (const QString& path : files()) menu_->addAction(path, this, [this, path] { open_(path); });
  menu_->setEnabled(!menu_->isEmpty());
}

}  // namespace tetskin::gui
