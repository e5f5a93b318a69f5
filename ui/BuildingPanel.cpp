// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/BuildingPanel.h"

#include "core/base/InputLimits.h"
#include "core/codes/Atc306.h"
#include "core/codes/Eurocode8.h"
#include "core/codes/Ubc1976.h"
#include "core/codes/Ubc1997.h"
#include "ui/NumberField.h"
#include "ui/TextField.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

#include <cmath>
#include <iterator>

namespace kinstab::ui {

namespace {
const std::pair<StructuralSystem, const char*> systems[] = {
    {StructuralSystem::DualFrameWall,
     QT_TRANSLATE_NOOP("BuildingPanel", "Dual: moment frame + shear walls")},
    {StructuralSystem::SteelMomentFrame, QT_TRANSLATE_NOOP("BuildingPanel", "Steel moment frame")},
    {StructuralSystem::ConcreteMomentFrame,
     QT_TRANSLATE_NOOP("BuildingPanel", "Concrete moment frame")},
    {StructuralSystem::SteelBracedEccentric,
     QT_TRANSLATE_NOOP("BuildingPanel", "Steel eccentrically braced frame")},
    {StructuralSystem::ShearWall,
     QT_TRANSLATE_NOOP("BuildingPanel", "Shear walls (concrete or masonry)")},
    {StructuralSystem::BracedFrame,
     QT_TRANSLATE_NOOP("BuildingPanel", "Concentrically braced frame")},
    {StructuralSystem::Other, QT_TRANSLATE_NOOP("BuildingPanel", "Other")},
};
const std::pair<Occupancy, const char*> occupancies[] = {
    {Occupancy::Standard, QT_TRANSLATE_NOOP("BuildingPanel", "Standard (offices, dwellings)")},
    {Occupancy::Assembly, QT_TRANSLATE_NOOP("BuildingPanel", "Assembly (> 300 in one room)")},
    {Occupancy::Hazardous, QT_TRANSLATE_NOOP("BuildingPanel", "Hazardous contents")},
    {Occupancy::Essential,
     QT_TRANSLATE_NOOP("BuildingPanel", "Essential (hospital, fire station)")},
};
} // namespace

BuildingPanel::BuildingPanel(QWidget* parent)
    : InputPanel(parent), m_name(new TextField(limits::kMaxNameChars, this)),
      m_estimate(new QCheckBox(tr("Estimate by each code's formula"), this)),
      m_estimates(new QLabel(this)), m_system(new QComboBox(this)), m_systemNote(new QLabel(this)),
      m_occupancy(new QComboBox(this)) {
    buildNameRow();
    buildSizeFields();
    buildPeriodRows();
    buildUseRows();

    connect(m_estimate, &QCheckBox::toggled, this, [this] {
        m_period->setEnabled(!m_estimate->isChecked());
        updateEstimate();
        emit changed();
    });
    for (QComboBox* c : {m_system, m_occupancy})
        connect(c, &QComboBox::currentIndexChanged, this, &InputPanel::changed);
    connect(m_name, &TextField::edited, this, &InputPanel::changed);
    connect(this, &InputPanel::changed, this, &BuildingPanel::updateEstimate);
    setBuilding(Building{});
}

// The form's rows, top to bottom: the name; N, h_n and D; the period; the system and use.
void BuildingPanel::buildNameRow() {
    m_name->setToolTip(tr("A name for the building, printed on exports and reports."));
    m_name->setObjectName(QStringLiteral("buildingName"));
    m_name->lineEdit()->setToolTip(m_name->toolTip());
    auto* nameLabel = new QLabel(tr("&Name:"), this);
    nameLabel->setBuddy(m_name->lineEdit());
    form()->addRow(nameLabel, m_name);
}

void BuildingPanel::buildSizeFields() {
    m_stories =
        addField("stories", tr("&Stories:"), QString(),
                 tr("Number of stories above the base, N. The top floor's force ratio is what "
                    "the slab on the top floor feels."));
    m_stories->setCheck([](double v) {
        return v >= 1 && v <= kMaxStories && v == std::floor(v)
                   ? QString()
                   : tr("a whole number from 1 to %1 (got %2)").arg(kMaxStories).arg(v);
    });
    m_height = addField("height", tr("&Height h_n:"), QString(),
                        tr("Height of the roof above the base, h_n. Enters the period formulas "
                           "(T = 0.05 h_n/√D) and the vertical force distribution."));
    // The limits are in the stored unit, which a loaded file may change.
    m_height->setCheck(
        [this](double v) { return rangeCheck(0, maxBuildingHeight(m_unit), false)(v); });
    m_dimension = addField("planDimension", tr("&Plan dimension D:"), QString(),
                           tr("Plan dimension of the building parallel to the earthquake force, D "
                              "(UBC) or L (ATC 3-06). Enters T = 0.05 h_n/√D."));
    m_dimension->setCheck(
        [this](double v) { return rangeCheck(0, maxPlanDimension(m_unit), false)(v); });
}

void BuildingPanel::buildPeriodRows() {
    m_estimate->setToolTip(tr("Leave the period to each code's own formula instead of entering a "
                              "computed or measured fundamental period."));
    form()->addRow(QString(), m_estimate);
    m_period = addField("period", tr("&Period T:"), tr("s"),
                        tr("Fundamental period of the building. The floor motion's frequency is "
                           "taken as f = 1/T; the paper's building has T = 1.0 s."));
    m_period->setCheck(rangeCheck(kMinPeriodS, kMaxPeriodS));
    m_estimates->setWordWrap(true);
    form()->addRow(QString(), m_estimates);
}

void BuildingPanel::buildUseRows() {
    for (const auto& entry : systems)
        m_system->addItem(tr(entry.second));
    m_system->setToolTip(tr("Lateral-force-resisting system: it chooses each code's period "
                            "formula. K, R and q are the Codes panel's own inputs."));
    form()->addRow(tr("S&ystem:"), m_system);
    m_systemNote->setObjectName(QStringLiteral("systemNote"));
    m_systemNote->setWordWrap(true);
    form()->addRow(QString(), m_systemNote);
    for (const auto& entry : occupancies)
        m_occupancy->addItem(tr(entry.second));
    m_occupancy->setToolTip(tr("Use of the building: each code's importance factor follows from it "
                               "unless a code's own input overrides it."));
    form()->addRow(tr("&Occupancy:"), m_occupancy);
}

Building BuildingPanel::building() const {
    Building b = m_kept;
    b.name = m_name->text();
    b.unit = m_unit;
    b.stories = static_cast<int>(m_stories->value().value_or(b.stories));
    b.height = m_height->value().value_or(b.height);
    b.planDimension = m_dimension->value().value_or(b.planDimension);
    b.period = m_estimate->isChecked() ? std::nullopt : m_period->value();
    b.system = systems[m_system->currentIndex()].first;
    b.occupancy = occupancies[m_occupancy->currentIndex()].first;
    // Story data from a file only fit the building they came with.
    if (static_cast<int>(b.storyWeights.size()) != b.stories) b.storyWeights.clear();
    if (static_cast<int>(b.storyHeights.size()) != b.stories || b.height != m_kept.height)
        b.storyHeights.clear();
    return b;
}

QStringList BuildingPanel::extraProblems() const {
    if (m_name->isValid()) return {};
    return {tr("Name: %1").arg(m_name->error())};
}

void BuildingPanel::setBuilding(const Building& b) {
    m_kept = b;
    m_name->setText(b.name);
    m_unit = b.unit;
    // Stored in the file's unit, shown in the application's (View → Units).
    for (NumberField* f : {m_height, m_dimension})
        f->setLength(LengthScale::Structure, metresPerUnit(b.unit));
    m_stories->setValue(b.stories);
    m_height->setValue(b.height);
    m_dimension->setValue(b.planDimension);
    m_estimate->setChecked(!b.period);
    if (b.period) m_period->setValue(*b.period);
    m_period->setEnabled(b.period.has_value());
    for (int i = 0; i < static_cast<int>(std::size(systems)); ++i)
        if (systems[i].first == b.system) m_system->setCurrentIndex(i);
    for (int i = 0; i < static_cast<int>(std::size(occupancies)); ++i)
        if (occupancies[i].first == b.occupancy) m_occupancy->setCurrentIndex(i);
    updateEstimate();
}

QString BuildingPanel::systemNote() const {
    return m_systemNote->text();
}

void BuildingPanel::updateEstimate() {
    // What the system drives, said beside it: with T entered, nothing (issue 30: a change of
    // system changed nothing and nothing said so).
    m_systemNote->setText(
        m_estimate->isChecked()
            ? tr("The system sets each code's period formula (below); K, R and q are entered "
                 "under Codes.")
            : tr("With T entered the system changes no result: it only chooses the period "
                 "formulas, and K, R and q are entered under Codes."));
    if (!isValid()) {
        m_estimates->clear();
        return;
    }
    Building b = building();
    b.period.reset();
    try {
        m_estimates->setText(
            tr("Formula periods: UBC 1976 %1 s, ATC 3-06 %2 s, UBC 1997 %3 s, EC8 %4 s")
                .arg(ubc1976FormulaPeriod(b), 0, 'f', 3)
                .arg(atc306FormulaPeriod(b), 0, 'f', 3)
                .arg(ubc1997FormulaPeriod(b), 0, 'f', 3)
                .arg(eurocode8FormulaPeriod(b), 0, 'f', 3));
    } catch (const std::exception& e) {
        m_estimates->setText(QString::fromStdString(e.what()));
    }
}

} // namespace kinstab::ui
