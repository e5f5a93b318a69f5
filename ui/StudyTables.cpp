// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/StudyTables.h"

#include "ui/RecordMetricsText.h"

#include <QCoreApplication>
#include <QHeaderView>
#include <QTableWidget>

#include <map>
#include <utility>

namespace kinstab::ui {

namespace {

QString tr(const char* text) {
    return QCoreApplication::translate("StudyTab", text);
}

QString number(double x) {
    return QString::number(x, 'g', 4);
}

QString number(const std::optional<double>& x) {
    return x ? number(*x) : QStringLiteral("–");
}

// Four rows at least under the header: the tab's scroll area scrolls rather than the splitter
// squeezing the table to one row.
QTableWidget* makeTable(QWidget* parent, const QStringList& headers) {
    auto* t = new QTableWidget(0, static_cast<int>(headers.size()), parent);
    t->setHorizontalHeaderLabels(headers);
    t->setEditTriggers(QAbstractItemView::NoEditTriggers);
    t->horizontalHeader()->setStretchLastSection(true);
    t->setMinimumHeight(t->horizontalHeader()->sizeHint().height() +
                        4 * t->verticalHeader()->defaultSectionSize() + 2 * t->frameWidth());
    return t;
}

void setRow(QTableWidget* t, int row, const QStringList& cells) {
    for (int c = 0; c < cells.size(); ++c)
        t->setItem(row, c, new QTableWidgetItem(cells[c]));
}

} // namespace

QTableWidget* makeStudyCaseTable(QWidget* parent) {
    QStringList headers = {tr("Record"),        tr("μ"),   tr("t* s"), tr("Driving motion"),
                           tr("Critical IM g"), tr("Runs")};
    headers += recordMetricsHeaders();
    QTableWidget* t = makeTable(parent, headers);
    // Thirteen columns: the record's path elided on the left keeps its file name in view (the
    // whole path in the cell's tooltip).
    t->setWordWrap(false);
    t->setTextElideMode(Qt::ElideLeft);
    t->setColumnWidth(0, 240);
    for (int c = 6; c < t->columnCount(); ++c)
        t->horizontalHeaderItem(c)->setToolTip(recordMetricsToolTip());
    return t;
}

QTableWidget* makeStudySetTable(QWidget* parent) {
    QTableWidget* t =
        makeTable(parent, {tr("Set"), tr("μ"), tr("t* s"), tr("Driving motion"), tr("Records"),
                           tr("Censored"), tr("Mean g"), tr("Median g"), tr("σ g"), tr("σ ln"),
                           tr("Fit median g"), tr("β")});
    t->setObjectName(QStringLiteral("studySets")); // tests find it by name
    t->setToolTip(tr("Per parameter set, over the records that collapse: the mean, median and "
                     "standard deviation (n − 1) of the critical intensity and of its natural "
                     "logarithm; censored: records that did not collapse up to the search "
                     "limit. Fit: the lognormal fragility with the censored records."));
    return t;
}

// The μ and t* columns: the slab's, or for a block study the block's μ and its size (the
// block has no t*; its whole description is the cells' tooltip).
namespace {
std::pair<QString, QString> slabOrBlockCells(const StudyRow& r) {
    if (!r.block) return {number(r.mu), number(r.tstar)};
    const StudyBlock& b = *r.block;
    return {b.mu ? number(*b.mu) : tr("no sliding"),
            tr("block %1×%2 m").arg(number(2 * b.block.halfWidth), number(2 * b.block.halfHeight))};
}
} // namespace

void fillStudyCaseTable(QTableWidget* t, const std::vector<StudyRow>& rows,
                        const std::vector<StudyRecordMetrics>& metrics) {
    std::map<std::string, const RecordMetrics*> byRecord;
    for (const StudyRecordMetrics& m : metrics)
        byRecord[m.record] = &m.metrics;
    t->setRowCount(static_cast<int>(rows.size()));
    for (int i = 0; i < t->rowCount(); ++i) {
        const StudyRow& r = rows[static_cast<std::size_t>(i)];
        QStringList cells = {QString::fromStdString(studyRecordText(r)),
                             slabOrBlockCells(r).first,
                             slabOrBlockCells(r).second,
                             QString::fromStdString(studyDriverText(r)),
                             r.criticalIntensity
                                 ? number(*r.criticalIntensity)
                                 : tr("none up to %1 g").arg(number(r.limitIntensity)),
                             QString::number(r.runs)};
        if (const auto it = byRecord.find(r.record); it != byRecord.end())
            cells += recordMetricsCells(*it->second);
        setRow(t, i, cells);
        t->item(i, 0)->setToolTip(cells[0]);
    }
    for (int c = 1; c < t->columnCount(); ++c)
        t->resizeColumnToContents(c);
}

void fillStudySetTable(QTableWidget* t, const std::vector<Fragility>& sets) {
    t->setRowCount(static_cast<int>(sets.size()));
    for (int i = 0; i < t->rowCount(); ++i) {
        const Fragility& f = sets[static_cast<std::size_t>(i)];
        const RecordStatistics& s = f.statistics;
        setRow(t, i,
               {QString::number(f.parameters.set + 1), slabOrBlockCells(f.parameters).first,
                slabOrBlockCells(f.parameters).second,
                QString::fromStdString(studyDriverText(f.parameters)), QString::number(f.records),
                QString::number(s.censored), number(s.meanG), number(s.medianG), number(s.stdG),
                number(s.stdLn), f.fit ? number(f.fit->median) : tr("no fit"),
                f.fit ? number(f.fit->beta) : QStringLiteral("–")});
    }
    t->resizeColumnsToContents();
}

} // namespace kinstab::ui
