// SPDX-License-Identifier: AGPL-3.0-or-later
#pragma once
// Combo boxes over an enum's schema (OptionSchema.h): the names it
// offers, in its order, with their help as the tip; and the value a box
// names.

#include <QComboBox>
#include <QString>
#include <QStringList>
#include <string>

#include "tetskin/core/OptionSchema.h"

namespace tetskin::gui {

// A box named `name` (for tests and the command line) offering `items`.
inline QComboBox* combo(const char* name, const QStringList& items) {
  auto* c = new QComboBox;
  c->setObjectName(name);
  c->addItems(items);
  return c;
}

// (`tip`: the names' help unless given.)
template <SchemaEnum E>
QComboBox* enumCombo(const char* name, E current, const std::string& tip = helpOf<E>()) {
  QStringList items;
  for (const std::string& item : namesOf<E>()) items << QString::fromStdString(item);
  QComboBox* c = combo(name, items);
  c->setCurrentText(toString(current));
  c->setToolTip(QString::fromStdString(tip));
  return c;
}

// The same for an enum option: its help (OptionSchema.h), then `note`
// (what it means in this box's place), as the tip.
template <SchemaEnum E>
QComboBox* enumCombo(const char* name, const EnumOption<E>& option, E current,
                     const std::string& note = "") {
  return enumCombo(name, current, option.fullHelp() + note);
}

template <SchemaEnum E>
E chosen(const QComboBox* box) {
  return fromName<E>(box->currentText().toStdString());
}

}  // namespace tetskin::gui
