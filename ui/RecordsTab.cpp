// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordsTab.h"

#include "ui/RecordPreview.h"

#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace kinstab::ui {

RecordsTab::RecordsTab(QWidget* parent)
    : QWidget(parent), m_preview(new RecordPreview), m_message(new QLabel) {
    auto* open = new QPushButton(tr("Open record…"), this);
    open->setToolTip(tr("A ground or floor accelerogram: PEER NGA .AT2, COSMOS V1/V2, CSMIP V2 or "
                        "plain text (time, acceleration)."));
    m_message->setWordWrap(true);
    auto* bar = new QHBoxLayout;
    bar->addWidget(open);
    bar->addWidget(m_message, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_preview, 1);
    connect(open, &QPushButton::clicked, this, &RecordsTab::chooseFile);
    if (m_preview->loadFile(RecordPreview::defaultVerticalRecord()))
        m_message->setText(RecordPreview::defaultVerticalNote());
}

bool RecordsTab::open(const QString& path) {
    if (m_preview->loadFile(path)) {
        m_message->setStyleSheet({});
        m_message->setText(path);
        return true;
    }
    m_message->setStyleSheet(QStringLiteral("color: #b00020"));
    m_message->setText(m_preview->errorText());
    return false;
}

QString RecordsTab::errorText() const {
    return m_preview->errorText();
}

void RecordsTab::chooseFile() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open accelerogram"), {},
                                                      RecordPreview::fileDialogFilter());
    if (!path.isEmpty()) open(path);
}

} // namespace kinstab::ui
