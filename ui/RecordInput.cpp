// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordInput.h"

#include "core/base/InputLimits.h"
#include "ui/ProjectFolder.h"

#include "ui/NumberField.h"
#include "ui/RecordPreview.h"
#include "ui/StaleFrame.h"

#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace kinstab::ui {

RecordInput::RecordInput(QWidget* parent)
    : QWidget(parent), m_file(new QLineEdit(this)), m_browse(new QPushButton(tr("Browse…"), this)),
      m_message(new QLabel(this)), m_result(new QLabel(this)),
      m_peak(new NumberField(tr("g"), this)), m_preview(new RecordPreview(this)) {
    m_file->setObjectName("recordFile");
    m_file->setPlaceholderText(tr("accelerogram file (.AT2, COSMOS, CSMIP, text)"));
    m_file->setToolTip(tr("The horizontal ground (or floor) record that drives the slab."));
    m_message->setObjectName("recordMessage");
    m_message->setWordWrap(true);
    m_peak->setObjectName("recordPeak");
    m_peak->setOptional(tr("as recorded"));
    m_peak->setCheck(rangeCheck(kTargetPeakInput.range));
    m_peak->setFieldToolTip(tr("Peak acceleration the motion under the slab is scaled to (after "
                               "the floor filter). Empty: the record as it is."));
    auto* fileRow = new QHBoxLayout;
    fileRow->addWidget(m_file, 1);
    fileRow->addWidget(m_browse);
    auto* form = new QFormLayout;
    form->addRow(tr("Record:"), fileRow);
    form->addRow(QString(), m_message);
    form->addRow(tr("Target peak:"), m_peak);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(form);
    m_result->setObjectName("recordResult");
    m_result->setWordWrap(true);
    layout->addWidget(m_result);
    layout->addWidget(m_preview, 1);
    connect(m_browse, &QPushButton::clicked, this, &RecordInput::chooseFile);
    connect(m_file, &QLineEdit::editingFinished, this, [this] {
        if (m_file->text() != QString::fromStdString(m_preview->record()
                                                         ? m_preview->record()->sourceFile
                                                         : std::string()))
            loadFile(m_file->text());
    });
    connect(m_peak, &NumberField::edited, this, &RecordInput::changed);
    connect(m_preview, &RecordPreview::recordChanged, this, &RecordInput::changed);
    showError(tr("no record chosen"));
}

void RecordInput::showError(const QString& text) {
    m_message->setStyleSheet(QStringLiteral("color: #b00020"));
    m_message->setText(text);
}

bool RecordInput::loadFile(const QString& path) {
    m_file->setText(path);
    m_loaded = !path.isEmpty() && m_preview->loadFile(path, m_read);
    if (!m_loaded)
        showError(path.isEmpty() ? tr("no record chosen") : m_preview->errorText());
    else {
        m_message->setStyleSheet({});
        m_message->setText(QString::fromStdString(m_preview->record()->name));
    }
    emit changed();
    return m_loaded;
}

void RecordInput::setResult(const QString& text, bool error) {
    m_resultText = text;
    m_resultError = error;
    showResult();
}

void RecordInput::setResultStale(bool stale) {
    m_resultStale = stale;
    showResult();
}

void RecordInput::showResult() {
    const bool stale = m_resultStale && !m_resultText.isEmpty();
    m_result->setStyleSheet(m_resultError ? QStringLiteral("color: #b00020")
                            : stale       ? QStringLiteral("color: #8a8a8a")
                                          : QString());
    m_result->setText(stale ? StaleFrame::staleText() + QLatin1Char('\n') + m_resultText
                            : m_resultText);
}

QString RecordInput::resultText() const {
    return m_result->text();
}

bool RecordInput::isReady() const {
    return m_loaded && m_peak->isValid();
}

QString RecordInput::problem() const {
    if (!m_loaded) return tr("Record: %1").arg(m_message->text());
    if (!m_peak->isValid()) return tr("Target peak: %1").arg(m_peak->error());
    return {};
}

std::optional<RecordExcitation> RecordInput::record() const {
    if (!m_loaded) return std::nullopt;
    RecordExcitation e;
    e.file = m_file->text().toStdString();
    e.read = m_read;
    e.targetPeak = m_peak->value();
    e.scaleFactor = m_scaleFactor;
    e.floor = m_preview->floorFilter();
    return e;
}

void RecordInput::setRecord(const RecordExcitation& e) {
    m_read = e.read;
    m_scaleFactor = e.scaleFactor;
    m_peak->setOptionalValue(e.targetPeak);
    m_preview->setFloorFilter(e.floor);
    loadFile(QString::fromStdString(e.file));
}

void RecordInput::chooseFile() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open accelerogram"), inOpenProjectFolder(), RecordPreview::fileDialogFilter());
    if (path.isEmpty()) return;
    m_read = {}; // a new file: its own header decides
    loadFile(path);
}

} // namespace kinstab::ui
