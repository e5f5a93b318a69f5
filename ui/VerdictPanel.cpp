// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/VerdictPanel.h"

#include "report/CodeStyle.h"

#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace kinstab::ui {

namespace {
enum Column { ColCode, ColRatio, ColACrit, ColMargin, ColVerdict, Columns };
} // namespace

VerdictPanel::VerdictPanel(QWidget* parent)
    : QWidget(parent), m_table(new QTableWidget(0, Columns, this)), m_note(new QLabel(this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_table->setHorizontalHeaderLabels(
        {tr("Code"), tr("Ratio (g)"), tr("A_crit (g)"), tr("Margin"), tr("Verdict")});
    m_table->horizontalHeaderItem(ColRatio)->setToolTip(
        tr("Top-floor lateral force over the top floor's weight, as the code requires it: the peak "
           "floor "
           "acceleration the code designs the slab's floor for, in g."));
    m_table->horizontalHeaderItem(ColACrit)->setToolTip(
        tr("Smallest floor-acceleration amplitude that slides the slab off its walls at f = 1/T."));
    m_table->horizontalHeaderItem(ColMargin)->setToolTip(
        tr("A_crit / ratio: above 1 the members overstress before the slab can fall."));
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(m_table);
    m_note->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // no wrap: see SurfaceView
    layout->addWidget(m_note);
}

int VerdictPanel::rowCount() const {
    return m_table->rowCount();
}

QString VerdictPanel::codeText(int row) const {
    const QTableWidgetItem* item = m_table->item(row, ColCode);
    return item ? item->text() : QString();
}

QString VerdictPanel::verdictText(int row) const {
    const QTableWidgetItem* item = m_table->item(row, ColVerdict);
    return item ? item->text() : QString();
}

void VerdictPanel::setRow(int row, const std::string& code, const QString& title, double period,
                          double ratio, const QString& aCrit, const QString& margin,
                          const QString& verdict, const QColor& colour) {
    // The short name ("UBC 1976"): the dock is narrow; the full title is the tooltip.
    const QString cells[] = {report::shortCodeName(code), QString::number(ratio, 'f', 3), aCrit,
                             margin, verdict};
    for (int c = 0; c < Columns; ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        if (c != ColCode && c != ColVerdict)
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (c == ColVerdict) item->setForeground(colour);
        if (c == ColCode) item->setToolTip(tr("%1, T = %2 s").arg(title).arg(period, 0, 'f', 3));
        m_table->setItem(row, c, item);
    }
}

void VerdictPanel::setCodeResults(const std::vector<CodeResult>& results) {
    m_table->setRowCount(static_cast<int>(results.size()));
    QStringList notes;
    for (int i = 0; i < static_cast<int>(results.size()); ++i) {
        const CodeResult& r = results[static_cast<std::size_t>(i)];
        setRow(i, r.code, QString::fromStdString(r.title), r.periodSeconds, r.topRatio, tr("…"),
               tr("…"), tr("press Run"), palette().color(QPalette::PlaceholderText));
        if (r.topRatioWithoutFt)
            notes << tr("%1: %2 with F_t, %3 without (the paper's).")
                         .arg(QString::fromStdString(r.title))
                         .arg(r.topRatio, 0, 'f', 3)
                         .arg(*r.topRatioWithoutFt, 0, 'f', 3);
    }
    m_note->setText(results.empty() ? tr("No code selected.") : notes.join(QLatin1Char(' ')));
}

void VerdictPanel::setError(const QString& message) {
    m_table->setRowCount(0);
    m_note->setText(tr("<span style='color:#c0392b'>%1</span>").arg(message.toHtmlEscaped()));
}

void VerdictPanel::setCheck(const DesignCheckResult& check) {
    m_table->setRowCount(static_cast<int>(check.codes.size()));
    for (int i = 0; i < static_cast<int>(check.codes.size()); ++i) {
        const CodeVerdict& v = check.codes[static_cast<std::size_t>(i)];
        const bool kinetic = v.verdict == Verdict::KineticInstabilityGoverns;
        setRow(i, v.code, QString::fromStdString(v.title), v.periodSeconds, v.ratio,
               v.aCrit ? QString::number(*v.aCrit, 'f', 3) : tr("none ≤ limit"),
               v.margin ? QString::number(*v.margin, 'f', 2) : tr("—"),
               QString::fromStdString(kinstab::verdictText(v.verdict)),
               kinetic ? QColor(192, 57, 43) : QColor(30, 130, 60));
        m_table->item(i, ColVerdict)->setToolTip(QString::fromStdString(v.explanation));
    }
}

} // namespace kinstab::ui
