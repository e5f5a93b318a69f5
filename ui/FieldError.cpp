// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/FieldError.h"

#include <QLabel>
#include <QLineEdit>

namespace kinstab::ui {

void styleFieldError(QLabel* label) {
    label->setStyleSheet("color: #c0392b;");
    label->setWordWrap(true);
    label->hide();
}

bool showFieldError(const QString& error, QString& current, QLabel* label, QLineEdit* edit) {
    const bool changed = error != current;
    current = error;
    label->setText(error);
    label->setVisible(!error.isEmpty());
    edit->setStyleSheet(error.isEmpty() ? QString() : QStringLiteral("border: 1px solid #c0392b;"));
    return changed;
}

} // namespace kinstab::ui
