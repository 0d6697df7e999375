// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// File > Open Recent: the last files opened (absolute paths, newest first,
// at most 8), kept in the user's settings across sessions.

#include <QObject>
#include <QString>
#include <QStringList>
#include <functional>

class QMenu;

namespace tetskin::gui {

class RecentFiles : public QObject {
  Q_OBJECT
 public:
  // Fills `menu`; choosing an entry calls `open` with its path.
  RecentFiles(QMenu* menu, std::function<void(const QString&)> open);

  void remember(const QString& path);
  QStringList files() const;

 private:
  void refresh();
  QMenu* menu_;
  std::function<void(const QString&)> open_;
};

}  // namespace tetskin::gui
