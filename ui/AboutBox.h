// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Help → About: the version, the licence, how to cite, and the libraries with their versions.

#include <QDialog>

namespace kinstab::ui {

// The About text as HTML (also what the dialog shows).
QString aboutHtml();

class AboutBox : public QDialog {
    Q_OBJECT
public:
    explicit AboutBox(QWidget* parent = nullptr);
};

} // namespace kinstab::ui
