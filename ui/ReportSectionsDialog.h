// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// File → Export report…: the first step asks which optional sections to print, one check box
// per section of report/SectionCatalog.h (the same keys as `kinstab-cli report --sections`).

#include "report/SectionCatalog.h"

#include <QDialog>

#include <vector>

class QCheckBox;

namespace kinstab::ui {

class ReportSectionsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ReportSectionsDialog(const report::SectionSet& initial, QWidget* parent = nullptr);
    report::SectionSet sections() const;

    // Shows the dialog; false when the user cancels.
    static bool choose(QWidget* parent, report::SectionSet& sections);

private:
    std::vector<std::pair<QCheckBox*, std::string>> boxes_;
};

} // namespace kinstab::ui
