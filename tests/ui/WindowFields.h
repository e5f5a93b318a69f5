// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Finds an input field of the main window by its objectName, as the GUI tests address them;
// a missing one stops the test (a renamed field must not pass silently).

#include "ui/NumberField.h"

#include <QWidget>

namespace kinstab::testing {

inline ui::NumberField* namedField(const QWidget* root, const char* name) {
    auto* f = root->findChild<ui::NumberField*>(QString::fromLatin1(name));
    if (!f) qFatal("no field %s", name);
    return f;
}

} // namespace kinstab::testing
