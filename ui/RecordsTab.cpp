// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordsTab.h"

#include "ui/ProjectFolder.h"
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
    m_preview->clear();
    m_message->setText(tr("No record open."));
}

QString RecordsTab::messageText() const {
    return m_message->text();
}

void RecordsTab::showProject(const Project& p) {
    m_message->setStyleSheet({});
    if (p.record) {
        m_preview->setPlanarBase(false);
        if (!m_preview->loadFile(QString::fromStdString(p.record->file), p.record->read)) {
            m_message->setStyleSheet(QStringLiteral("color: #b00020"));
            m_message->setText(m_preview->errorText());
            return;
        }
        m_preview->setFloorFilter(p.record->floor);
        m_message->setText(
            p.record->floor
                ? tr("The project's record, through its floor filter (T = %1 s, ζ = %2 %).")
                      .arg(p.record->floor->period)
                      .arg(100.0 * p.record->floor->damping)
                : tr("The project's record, driving the slab directly (no floor filter)."));
        return;
    }
    if (p.model == ModelKind::Planar && p.planar.vertical != VerticalSource::None) {
        m_preview->setPlanarBase(true);
        const QString path = p.planar.vertical == VerticalSource::Rsn68Up
                                 ? RecordPreview::defaultVerticalRecord()
                                 : QString::fromStdString(p.planar.verticalPath);
        if (m_preview->loadFile(path))
            m_message->setText(tr("The planar project's vertical base motion, as recorded. %1")
                                   .arg(p.planar.vertical == VerticalSource::Rsn68Up
                                            ? RecordPreview::defaultVerticalNote()
                                            : path));
        return;
    }
    m_preview->clear();
    m_message->setText(
        tr("This project has no record: its excitation is the enveloped sine%1. "
           "Open a record to preview it.")
            .arg(p.model == ModelKind::Planar ? tr(", with no vertical motion") : QString()));
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
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open accelerogram"), inOpenProjectFolder(), RecordPreview::fileDialogFilter());
    if (!path.isEmpty()) open(path);
}

} // namespace kinstab::ui
