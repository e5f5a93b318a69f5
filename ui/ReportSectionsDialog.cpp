// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ReportSectionsDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace kinstab::ui {

using namespace kinstab::report;

ReportSectionsDialog::ReportSectionsDialog(const SectionSet& initial, QWidget* parent)
    : QDialog(parent) {
    setWindowTitle(tr("Report sections"));
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("The title block, the verdict on page 1 and the signature "
                                    "block are always printed. Further sections:")));
    for (const SectionEntry& e : sectionCatalog()) {
        auto* box = new QCheckBox(QString::fromUtf8(e.title));
        box->setChecked(initial.count(e.key) > 0);
        box->setObjectName(QStringLiteral("section_") + QString::fromUtf8(e.key));
        layout->addWidget(box);
        boxes_.push_back({box, e.key});
    }
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel |
                                         QDialogButtonBox::RestoreDefaults);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(buttons->button(QDialogButtonBox::RestoreDefaults), &QPushButton::clicked, this,
            [this] {
                const SectionSet d = defaultSections();
                for (const auto& [box, key] : boxes_)
                    box->setChecked(d.count(key) > 0);
            });
    layout->addWidget(buttons);
}

SectionSet ReportSectionsDialog::sections() const {
    SectionSet s;
    for (const auto& [box, key] : boxes_)
        if (box->isChecked()) s.insert(key);
    return s;
}

bool ReportSectionsDialog::choose(QWidget* parent, SectionSet& sections) {
    ReportSectionsDialog d(sections, parent);
    if (d.exec() != QDialog::Accepted) return false;
    sections = d.sections();
    return true;
}

} // namespace kinstab::ui
