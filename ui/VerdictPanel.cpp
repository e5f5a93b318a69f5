// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/VerdictPanel.h"

#include "report/CodeStyle.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace kinstab::ui {

namespace {
enum Column { ColBasis, ColCheck, ColDemand, ColCapacity, ColMargin, ColVerdict, Columns };

QString fixed(double x, int digits) {
    return QString::number(x, 'f', digits);
}

QString marginCell(const Comparison& x) {
    return QString::fromStdString(marginText(x));
}
} // namespace

VerdictPanel::VerdictPanel(QWidget* parent)
    : QWidget(parent), m_table(new QTableWidget(0, Columns, this)), m_note(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_table->setHorizontalHeaderLabels(
        {tr("Basis"), tr("Code"), tr("Demand"), tr("Capacity"), tr("Margin"), tr("Verdict")});
    m_table->horizontalHeaderItem(ColBasis)->setToolTip(
        tr("What the check rests on: sine (enveloped sine, ch. IV), planar (ch. VI), record (the "
           "project's record), floors (the building's floor motions under the ground record), risk "
           "(a study set's collapse fragility against the site's hazard curve)."));
    m_table->horizontalHeaderItem(ColDemand)->setToolTip(
        tr("The code's demand in g, in the check's intensity: the top-floor force ratio "
           "F_top/w_top, or for a floor check the ground acceleration of the code level; for a "
           "risk check the annual rate of the slab falling (1/yr)."));
    m_table->horizontalHeaderItem(ColCapacity)
        ->setToolTip(tr("The same intensity (g) at which the slab slides off its walls; for a risk "
                        "check the target annual rate (1/yr)."));
    m_table->horizontalHeaderItem(ColMargin)->setToolTip(
        tr("Capacity / demand: above 1 the check holds. The smallest margin governs."));
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    // The verdict takes what is left and wraps: the dock is narrow at 1280 x 800.
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(ColVerdict, QHeaderView::Stretch);
    m_table->setWordWrap(true);
    layout->addWidget(m_table);
    m_note->setWordWrap(true);
    layout->addWidget(m_note);
}

int VerdictPanel::rowCount() const {
    return m_table->rowCount();
}

QString VerdictPanel::codeText(int row) const {
    return row >= 0 && row < m_codes.size() ? m_codes[row] : QString();
}

QString VerdictPanel::checkText(int row) const {
    return row >= 0 && row < m_ids.size() ? m_ids[row] : QString();
}

QString VerdictPanel::basisText(int row) const {
    const QTableWidgetItem* item = m_table->item(row, ColBasis);
    return item ? item->text() : QString();
}

QString VerdictPanel::verdictText(int row) const {
    const QTableWidgetItem* item = m_table->item(row, ColVerdict);
    return item ? item->text() : QString();
}

QString VerdictPanel::governingText() const {
    return m_note->text();
}

void VerdictPanel::setRow(int row, const QStringList& cells, const QString& tooltip,
                          const QColor& colour) {
    for (int c = 0; c < Columns; ++c) {
        auto* item = new QTableWidgetItem(cells.value(c));
        if (c == ColDemand || c == ColCapacity || c == ColMargin)
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (c == ColVerdict) item->setForeground(colour);
        item->setToolTip(tooltip);
        m_table->setItem(row, c, item);
    }
}

void VerdictPanel::setCodeResults(const std::vector<CodeResult>& results) {
    m_table->setRowCount(static_cast<int>(results.size()));
    m_codes.clear();
    m_ids.clear();
    QStringList notes;
    for (int i = 0; i < static_cast<int>(results.size()); ++i) {
        const CodeResult& r = results[static_cast<std::size_t>(i)];
        m_codes << report::shortCodeName(r.code);
        setRow(
            i, {QString(), m_codes.back(), fixed(r.topRatio, 3), tr("…"), tr("…"), tr("press Run")},
            tr("%1, T = %2 s").arg(QString::fromStdString(r.title)).arg(r.periodSeconds, 0, 'f', 3),
            palette().color(QPalette::PlaceholderText));
        if (r.topRatioWithoutFt)
            notes << tr("%1: %2 with F_t, %3 without (the paper's).")
                         .arg(QString::fromStdString(r.title))
                         .arg(r.topRatio, 0, 'f', 3)
                         .arg(*r.topRatioWithoutFt, 0, 'f', 3);
    }
    m_note->setText(results.empty() ? tr("No code selected.") : notes.join(QLatin1Char(' ')));
    m_table->resizeRowsToContents();
}

void VerdictPanel::setError(const QString& message) {
    m_table->setRowCount(0);
    m_codes.clear();
    m_ids.clear();
    m_note->setText(tr("<span style='color:#c0392b'>%1</span>").arg(message.toHtmlEscaped()));
}

void VerdictPanel::setAssessment(const Assessment& a, const QString& scope) {
    m_table->setRowCount(static_cast<int>(a.checks.size()));
    m_codes.clear();
    m_ids.clear();
    for (int i = 0; i < static_cast<int>(a.checks.size()); ++i) {
        const Check& c = a.checks[static_cast<std::size_t>(i)];
        const Comparison& x = c.governing();
        m_codes << report::shortCodeName(c.code);
        m_ids << QString::fromStdString(c.id);
        const bool perLevel = c.basis == CheckBasis::Floors || c.basis == CheckBasis::Block;
        const QString level = perLevel && c.code == "asce7_22"
                                  ? (c.level == CheckLevel::MceR ? tr("\nMCE_R") : tr("\ndesign"))
                                  : QString();
        // A block's check names its block ("block.parapet.ec8": the name between the dots).
        const QString basis =
            c.basis == CheckBasis::Block
                ? QStringLiteral("block\n") + m_ids.back().section(QLatin1Char('.'), 1, 1)
                : QString::fromStdString(checkBasisName(c.basis));
        setRow(
            i,
            {basis, m_codes.back() + level, QString::fromStdString(quantityText(x, x.demand)),
             x.capacity ? QString::fromStdString(quantityText(x, *x.capacity)) : tr("none ≤ limit"),
             marginCell(x), QString::fromStdString(c.verdict)},
            tr("%1: %2\n%3 against %4 (%5)\nModel: %6\nExcitation: %7")
                .arg(m_ids.back(), QString::fromStdString(c.codeTitle),
                     QString::fromStdString(x.demandName), QString::fromStdString(x.capacityName),
                     QString::fromStdString(x.intensity), QString::fromStdString(c.model),
                     QString::fromStdString(c.excitation)),
            c.holds ? QColor(30, 130, 60) : QColor(192, 57, 43));
        if (a.governing == static_cast<std::size_t>(i))
            for (int col = 0; col < Columns; ++col) {
                QFont f = m_table->item(i, col)->font();
                f.setBold(true);
                m_table->item(i, col)->setFont(f);
            }
    }
    const Check* g = a.governingCheck();
    const QString governing =
        g ? tr("Governing: %1, margin %2 — %3.")
                .arg(QString::fromStdString(g->id), marginCell(g->governing()),
                     QString::fromStdString(g->verdict))
          : tr("No check ran.");
    m_note->setText(scope.isEmpty() ? governing : scope + "\n" + governing);
    m_note->setToolTip(QString::fromStdString(a.governingReason));
    m_table->resizeRowsToContents();
}

} // namespace kinstab::ui
