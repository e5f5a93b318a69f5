// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ModelPanel.h"

#include "core/excitation/FrequencyRange.h"
#include "core/slab/SlabInputs.h"
#include "core/slab/VerticalRecord.h"
#include "ui/NumberField.h"
#include "ui/RecordPreview.h"

#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace kinstab::ui {

namespace {
const QString errorStyle = QStringLiteral("color: #c0392b;");
} // namespace

ModelPanel::ModelPanel(QWidget* parent)
    : InputPanel(parent), m_model(new QComboBox(this)), m_normalization(new QComboBox(this)),
      m_vertical(new QComboBox(this)), m_fileRow(new QWidget(this)),
      m_path(new QLineEdit(m_fileRow)), m_browse(new QPushButton(tr("Browse…"), m_fileRow)),
      m_pathError(new QLabel(m_fileRow)), m_note(new QLabel(this)) {
    m_model->setObjectName(QStringLiteral("model"));
    m_model->addItem(tr("1-DOF (across the walls)"));
    m_model->addItem(tr("Planar (2-DOF, with vertical)"));
    m_model->addItem(tr("Free-standing block"));
    m_model->setToolTip(
        tr("1-DOF: the slab slides across the walls only (Furgerson 1980 ch. IV).\n"
           "Planar: it slides in both horizontal directions, friction along the relative "
           "velocity, normal force 1 + a_z (ch. VI); slower, 2–5 ms of CPU per point.\n"
           "Free-standing block: a rigid block that rocks, slides and may overturn under a "
           "pulse; Run maps overturning over a_p/(αg) and ω_p/p (Zhang & Makris 2001)."));
    form()->addRow(tr("&Model:"), m_model);
    buildPlanarRows();
    buildBlockRows();
    connect(m_model, &QComboBox::currentIndexChanged, this, [this] {
        if (!isBlock()) m_slabIndex = m_model->currentIndex();
        updateMode();
        emit changed();
    });
    connect(m_vertical, &QComboBox::currentIndexChanged, this, [this] {
        updateMode();
        emit changed();
    });
    connect(m_normalization, &QComboBox::currentIndexChanged, this, &InputPanel::changed);
    connect(m_path, &QLineEdit::editingFinished, this, &ModelPanel::checkVerticalFile);
    connect(m_browse, &QPushButton::clicked, this, &ModelPanel::browse);
    load(ModelKind::Slab1D, PlanarSettings{});
}

void ModelPanel::buildPlanarRows() {
    m_fy = addField("fy", tr("f_&y:"), tr("Hz"),
                    tr("Frequency of the motion along the walls. The paper's Figs. 37–42 use "
                       "0.2, 0.5, 1, 2, 5 and 10 Hz; the critical amplitude rises with f_y."));
    m_fy->setCheck(rangeCheck(kFyInput.range));
    m_ratio = addField("ayRatio", tr("A_y / A_x:"), QString(),
                       tr("Amplitude along the walls over the amplitude across them. The paper "
                          "takes 0.9, Pacoima Dam's ratio of horizontal peaks."));
    m_ratio->setCheck(rangeCheck(kAyRatioInput.range));
    m_theta = addField("theta", tr("Θ (along):"), QString(),
                       tr("Along-wall limit: the slab falls when its slip along the walls exceeds "
                          "Θ = 2 wall length / wall width (half-widths). Default 20."));
    m_theta->setCheck(rangeCheck(kThetaInput.range));
    m_normalization->addItem(tr("product (e × sine)"));
    m_normalization->addItem(tr("envelope (ch. VI)"));
    m_normalization->setToolTip(
        tr("How each horizontal component's S_max is taken. Product: each peaks at its "
           "amplitude (ch. IV). Envelope: as printed in ch. VI, somewhat below it."));
    form()->addRow(tr("S_max:"), m_normalization);
    m_vertical->setObjectName(QStringLiteral("verticalSource"));
    m_vertical->addItem(tr("None (gravity only)"));
    m_vertical->addItem(tr("RSN68 UP (for Pacoima Dam)"));
    m_vertical->addItem(tr("Record file…"));
    m_vertical->setToolTip(RecordPreview::defaultVerticalNote());
    form()->addRow(tr("&Vertical:"), m_vertical);
    // The dock is narrow: combos may elide rather than widen the panel.
    for (QComboBox* c : {m_model, m_normalization, m_vertical}) {
        c->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        c->setMinimumContentsLength(12);
    }
    auto* column = new QVBoxLayout(m_fileRow);
    column->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    m_path->setObjectName(QStringLiteral("verticalPath"));
    m_path->setPlaceholderText(tr("AT2, COSMOS, CSMIP V2 or text record"));
    row->addWidget(m_path, 1);
    row->addWidget(m_browse);
    column->addLayout(row);
    m_pathError->setStyleSheet(errorStyle);
    m_pathError->setWordWrap(true);
    column->addWidget(m_pathError);
    form()->addRow(tr("Record:"), m_fileRow);
    m_note->setWordWrap(true);
    m_note->setText(RecordPreview::defaultVerticalNote());
    form()->addRow(QString(), m_note);
}

void ModelPanel::updateMode() {
    const bool planar = isPlanar();
    for (NumberField* f : {m_fy, m_ratio, m_theta}) {
        f->setEnabled(planar); // disabled fields do not gate Run (InputPanel)
        form()->setRowVisible(f, planar);
    }
    form()->setRowVisible(m_normalization, planar);
    form()->setRowVisible(m_vertical, planar);
    const auto v = static_cast<VerticalSource>(m_vertical->currentIndex());
    form()->setRowVisible(m_fileRow, planar && v == VerticalSource::File);
    form()->setRowVisible(m_note, planar && v == VerticalSource::Rsn68Up);
    const bool block = isBlock();
    for (NumberField* f : {m_b, m_h, m_mu, m_restitution, m_aMax, m_wMax, m_points}) {
        f->setEnabled(block);
        form()->setRowVisible(f, block);
    }
    for (QWidget* w : std::initializer_list<QWidget*>{m_equations, m_pulse, m_blockNote})
        form()->setRowVisible(w, block);
    checkVerticalFile();
}

// Reads the record once when its path is set, so a broken file is marked before Run.
void ModelPanel::checkVerticalFile() {
    QString error;
    const auto v = static_cast<VerticalSource>(m_vertical->currentIndex());
    if (isPlanar() && v == VerticalSource::File) {
        PlanarSettings s;
        s.vertical = v;
        s.verticalPath = m_path->text().trimmed().toStdString();
        if (s.verticalPath.empty()) {
            error = tr("name the vertical record file");
        } else {
            try {
                loadVerticalRecord(s);
            } catch (const std::exception& e) {
                error = QString::fromStdString(e.what());
            }
        }
    }
    m_pathError->setText(error);
    m_pathError->setVisible(!error.isEmpty());
    if (error == m_verticalError) return;
    m_verticalError = error;
    emit changed();
}

void ModelPanel::browse() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Vertical record"), m_path->text(),
                                                      tr("Records (*.AT2 *.V1 *.V2 *.txt "
                                                         "*.acc *.dat);;All files (*)"));
    if (path.isEmpty()) return;
    m_path->setText(path);
    checkVerticalFile();
}

QStringList ModelPanel::extraProblems() const {
    if (m_verticalError.isEmpty()) return {};
    return {tr("Vertical record: %1").arg(m_verticalError)};
}

bool ModelPanel::isPlanar() const {
    return m_model->currentIndex() == 1;
}

bool ModelPanel::isBlock() const {
    return m_model->currentIndex() == 2;
}

ModelKind ModelPanel::model() const {
    return (isBlock() ? m_slabIndex : m_model->currentIndex()) == 1 ? ModelKind::Planar
                                                                    : ModelKind::Slab1D;
}

PlanarSettings ModelPanel::settings() const {
    PlanarSettings s = m_loaded;
    s.fyHz = m_fy->value().value_or(s.fyHz);
    s.ayRatio = m_ratio->value().value_or(s.ayRatio);
    s.theta = m_theta->value().value_or(s.theta);
    s.normalization = m_normalization->currentIndex() == 0 ? PlanarNormalization::Product
                                                           : PlanarNormalization::Envelope;
    s.vertical = static_cast<VerticalSource>(m_vertical->currentIndex());
    s.verticalPath = m_path->text().trimmed().toStdString();
    return s;
}

void ModelPanel::load(ModelKind model, const PlanarSettings& s, const BlockMapSettings& b) {
    m_loaded = s;
    {
        const QSignalBlocker block(this); // one changed() at the end
        m_slabIndex = model == ModelKind::Planar ? 1 : 0;
        m_model->setCurrentIndex(b.selected ? 2 : m_slabIndex);
        showBlock(b);
        m_fy->setValue(s.fyHz);
        m_ratio->setValue(s.ayRatio);
        m_theta->setValue(s.theta);
        m_normalization->setCurrentIndex(s.normalization == PlanarNormalization::Product ? 0 : 1);
        m_vertical->setCurrentIndex(static_cast<int>(s.vertical));
        m_path->setText(QString::fromStdString(s.verticalPath));
        updateMode();
    }
    emit changed();
}

} // namespace kinstab::ui
