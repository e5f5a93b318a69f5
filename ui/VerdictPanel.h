// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The verdict: per code, the top-floor ratio F_top / w_top, the critical amplitude A_crit at
// the building's frequency, the margin A_crit / ratio and what governs, in words.

#include "core/check/DesignCheck.h"
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
    void setCheck(const DesignCheckResult& check);
    QString verdictText(int row) const; // for tests
    QString codeText(int row) const;    // for tests
    int rowCount() const;

private:
    void setRow(int row, const std::string& code, const QString& title, double period, double ratio,
                const QString& aCrit, const QString& margin, const QString& verdict,
                const QColor& colour);

    QTableWidget* m_table;
    QLabel* m_note;
};

} // namespace kinstab::ui
