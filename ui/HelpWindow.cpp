// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/HelpWindow.h"

#include <QAbstractTextDocumentLayout>
#include <QFile>
#include <QScrollBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace kinstab::ui {

QString userGuideMarkdown() {
    QFile f(QStringLiteral(":/docs/user-guide.md"));
    if (!f.open(QIODevice::ReadOnly))
        return QObject::tr("The user guide is missing from this build.");
    return QString::fromUtf8(f.readAll());
}

HelpWindow::HelpWindow(QWidget* parent) : QWidget(parent, Qt::Window), m_browser(new QTextBrowser) {
    setWindowTitle(tr("kinstab — User guide"));
    setObjectName(QStringLiteral("helpWindow"));
    m_browser->setOpenExternalLinks(true);
    // Images and links in the guide are relative to docs/; in the resources they sit there too.
    m_browser->setSearchPaths({QStringLiteral(":/docs")});
    m_browser->setMarkdown(userGuideMarkdown());
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_browser);
    resize(820, 720);
}

QStringList HelpWindow::sections() const {
    QStringList out;
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next())
        if (b.blockFormat().headingLevel() > 0) out << b.text();
    return out;
}

bool HelpWindow::showSection(const QString& title) {
    QTextDocument* doc = m_browser->document();
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() == 0 || b.text() != title) continue;
        m_browser->setTextCursor(QTextCursor(b));
        const QRectF r = doc->documentLayout()->blockBoundingRect(b);
        m_browser->verticalScrollBar()->setValue(static_cast<int>(r.top()));
        return true;
    }
    m_browser->verticalScrollBar()->setValue(0);
    return false;
}

} // namespace kinstab::ui
