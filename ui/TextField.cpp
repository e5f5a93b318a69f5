// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/TextField.h"

#include "core/base/DisplayText.h"
#include "ui/FieldError.h"

#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace kinstab::ui {

TextField::TextField(std::size_t maxChars, QWidget* parent)
    : QWidget(parent), m_maxChars(maxChars), m_edit(new QLineEdit(this)),
      m_errorLabel(new QLabel(this)) {
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(1);
    column->addWidget(m_edit);
    m_errorLabel->setObjectName(QStringLiteral("textError"));
    styleFieldError(m_errorLabel);
    column->addWidget(m_errorLabel);
    setFocusProxy(m_edit);
    connect(m_edit, &QLineEdit::textChanged, this, [this] {
        revalidate();
        emit edited();
    });
}

void TextField::setText(const std::string& text) {
    m_edit->setText(QString::fromStdString(text));
    revalidate(); // also when the text is unchanged: a fresh field starts checked
}

std::string TextField::text() const {
    return m_edit->text().trimmed().toStdString();
}

void TextField::revalidate() {
    const QString error =
        QString::fromStdString(displayTextProblem(text(), m_maxChars, TextLines::Single));
    if (showFieldError(error, m_error, m_errorLabel, m_edit)) emit validityChanged();
}

} // namespace kinstab::ui
