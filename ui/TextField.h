// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A one-line text input that the report prints (a name, a title-block field), checked as the
// project file is (core/base/DisplayText.h): what is wrong is shown beside the field, in red, as
// NumberField shows a number's, so an invisible bidirectional override or a pasted control
// character is named ("contains U+202E (a bidirectional override) at character 8") before the
// project is saved or the report signed.

#include <QWidget>

#include <cstddef>
#include <string>

class QLabel;
class QLineEdit;

namespace kinstab::ui {

class TextField : public QWidget {
    Q_OBJECT
public:
    // maxChars: characters (code points), not the UTF-16 units of QLineEdit::setMaxLength, so
    // that the field accepts what the project file accepts and no more.
    explicit TextField(std::size_t maxChars, QWidget* parent = nullptr);

    void setText(const std::string& text);
    std::string text() const; // trimmed of leading and trailing blanks, as stored
    bool isValid() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }
    QLineEdit* lineEdit() const { return m_edit; }

signals:
    void edited();          // the text changed (valid or not)
    void validityChanged(); // isValid() may have changed

private:
    void revalidate();

    std::size_t m_maxChars;
    QLineEdit* m_edit;
    QLabel* m_errorLabel;
    QString m_error;
};

} // namespace kinstab::ui
