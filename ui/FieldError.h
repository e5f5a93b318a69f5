// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The message an input field shows beside itself when its entry would be refused: one look for
// the number and text fields (a red line under the entry and a red border round it).

#include <QString>

class QLabel;
class QLineEdit;

namespace kinstab::ui {

// A hidden, word-wrapping red label for a field's error.
void styleFieldError(QLabel* label);
// Shows error under edit (or hides it when empty) and keeps it in current; true when it changed.
bool showFieldError(const QString& error, QString& current, QLabel* label, QLineEdit* edit);

} // namespace kinstab::ui
