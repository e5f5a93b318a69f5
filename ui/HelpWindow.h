// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The user guide (docs/user-guide.md, built into the program) in its own window, opened at a
// section: Help → User guide, or F1 at the section of the panel in focus.

#include <QWidget>

class QTextBrowser;

namespace kinstab::ui {

class HelpWindow : public QWidget {
    Q_OBJECT
public:
    explicit HelpWindow(QWidget* parent = nullptr);
    // Scrolls to the heading whose text is title; false (and the top) when there is none.
    bool showSection(const QString& title);
    // The headings of the guide, in order (for tests and the F1 table).
    QStringList sections() const;
    QTextBrowser* browser() const { return m_browser; }

private:
    QTextBrowser* m_browser;
};

// The guide's markdown as shipped in the resources.
QString userGuideMarkdown();

} // namespace kinstab::ui
