// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/HelpWindow.h"

#include <QAbstractTextDocumentLayout>
#include <QFile>
#include <QListWidget>
#include <QScrollBar>
#include <QSplitter>
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
    m_browser->setMarkdown(userGuideMarkdown());
    m_browser->document()->setDocumentMargin(16);
    // Contents: the guide's second- and third-level headings; a click shows that section.
    auto* contents = new QListWidget;
    contents->setObjectName(QStringLiteral("helpContents"));
    for (QTextBlock b = m_browser->document()->begin(); b.isValid(); b = b.next()) {
        const int level = b.blockFormat().headingLevel();
        if (level == 2 || level == 3)
            contents->addItem(QString(level == 3 ? 4 : 0, QLatin1Char(' ')) + b.text());
    }
    connect(contents, &QListWidget::itemClicked, this,
            [this](QListWidgetItem* item) { showSection(item->text().trimmed()); });
    auto* split = new QSplitter;
    split->addWidget(contents);
    split->addWidget(m_browser);
    split->setStretchFactor(1, 1);
    split->setSizes({220, 700});
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(split);
    resize(940, 720);
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
