// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The project's assessment (core/assessment): one row per check with its basis, demand,
// capacity, margin and verdict, the governing check named below the table. Before a run, the
// code ratios alone. The panel shows what core composed and judges nothing itself.

#include "core/assessment/Assessment.h"
#include "core/codes/CodeResult.h"

#include <QWidget>

class QLabel;
class QTableWidget;

namespace kinstab::ui {

class VerdictPanel : public QWidget {
    Q_OBJECT
public:
    explicit VerdictPanel(QWidget* parent = nullptr);

    // Code ratios alone (A_crit not yet computed), or an error naming the bad input.
    void setCodeResults(const std::vector<CodeResult>& results);
    void setError(const QString& message);
    // scope: empty for the project's whole assessment, else a sentence saying what the table
    // holds instead (this run's checks while the whole assessment is computed).
    void setAssessment(const Assessment& a, const QString& scope = {});
    QString verdictText(int row) const; // for tests
    QString codeText(int row) const;    // for tests: the code's short name
    QString checkText(int row) const;   // for tests: the check's id
    QString basisText(int row) const;   // for tests
    QString governingText() const;      // for tests
    int rowCount() const;

private:
    void setRow(int row, const QStringList& cells, const QString& tooltip, const QColor& colour);

    QTableWidget* m_table;
    QLabel* m_note;
    QStringList m_codes; // per row, the code's short name
    QStringList m_ids;   // per row, the check's id
};

} // namespace kinstab::ui
