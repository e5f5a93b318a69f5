// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ProjectInfoPanel.h"

#include "core/base/InputLimits.h"
#include "ui/TextField.h"

#include <QDate>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace kinstab::ui {

namespace {

struct FieldSpec {
    const char* label;
    std::string ProjectInfo::*member;
    const char* objectName;
};

const FieldSpec kFields[] = {
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Engineer of record"), &ProjectInfo::engineer,
     "engineer"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Licence / registration no."),
     &ProjectInfo::registration, "registration"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Firm"), &ProjectInfo::firm, "firm"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Client"), &ProjectInfo::client, "client"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Project number"), &ProjectInfo::projectNumber,
     "projectNumber"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Site address"), &ProjectInfo::siteAddress,
     "siteAddress"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Prepared by"), &ProjectInfo::preparedBy, "preparedBy"},
    {QT_TRANSLATE_NOOP("ProjectInfoPanel", "Checked by"), &ProjectInfo::checkedBy, "checkedBy"},
};

QString cell(const QTableWidget* t, int row, int column) {
    const QTableWidgetItem* item = t->item(row, column);
    return item ? item->text().trimmed() : QString();
}

} // namespace

ProjectInfoPanel::ProjectInfoPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    for (const FieldSpec& f : kFields) {
        auto* field = new TextField(limits::kMaxNameChars);
        field->lineEdit()->setObjectName(QString::fromLatin1(f.objectName));
        form->addRow(tr(f.label), field);
        fields_.push_back({field, f.member});
    }
    layout->addLayout(form);
    layout->addWidget(new QLabel(tr("Revisions (oldest first; the last is this issue; "
                                    "dates as YYYY-MM-DD):")));
    revisions_ = new QTableWidget(0, 3);
    revisions_->setObjectName(QStringLiteral("revisions"));
    revisions_->setHorizontalHeaderLabels({tr("Rev."), tr("Date"), tr("Description")});
    revisions_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(revisions_);
    revisionsError_ = new QLabel;
    revisionsError_->setObjectName(QStringLiteral("revisionsError"));
    revisionsError_->setStyleSheet("color: #c0392b;");
    revisionsError_->setWordWrap(true);
    revisionsError_->hide();
    layout->addWidget(revisionsError_);
    connect(revisions_, &QTableWidget::itemChanged, this, &ProjectInfoPanel::checkRevisions);
    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(tr("Add revision"));
    auto* remove = new QPushButton(tr("Remove revision"));
    connect(add, &QPushButton::clicked, this, &ProjectInfoPanel::addRevision);
    connect(remove, &QPushButton::clicked, this, [this] {
        const int row = revisions_->currentRow();
        revisions_->removeRow(row >= 0 ? row : revisions_->rowCount() - 1);
        checkRevisions();
    });
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch();
    layout->addLayout(buttons);
}

void ProjectInfoPanel::addRevision() {
    if (revisions_->rowCount() >= static_cast<int>(limits::kMaxRevisions)) return;
    const int row = revisions_->rowCount();
    revisions_->insertRow(row);
    revisions_->setItem(row, 0, new QTableWidgetItem(QString::number(row)));
    revisions_->setItem(row, 1, new QTableWidgetItem(QDate::currentDate().toString(Qt::ISODate)));
    revisions_->setItem(row, 2, new QTableWidgetItem);
}

void ProjectInfoPanel::setInfo(const ProjectInfo& info) {
    for (const auto& [field, member] : fields_)
        field->setText(info.*member);
    revisions_->setRowCount(0);
    for (const Revision& r : info.revisions) {
        const int row = revisions_->rowCount();
        revisions_->insertRow(row);
        revisions_->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(r.id)));
        revisions_->setItem(row, 1, new QTableWidgetItem(QString::fromStdString(r.date)));
        revisions_->setItem(row, 2, new QTableWidgetItem(QString::fromStdString(r.description)));
    }
    checkRevisions();
}

QString ProjectInfoPanel::problem() const {
    return QString::fromStdString(validateProjectInfo(info()));
}

void ProjectInfoPanel::checkRevisions() {
    ProjectInfo only;
    only.revisions = info().revisions;
    const QString e = QString::fromStdString(validateProjectInfo(only));
    revisionsError_->setText(e);
    revisionsError_->setVisible(!e.isEmpty());
}

ProjectInfo ProjectInfoPanel::info() const {
    ProjectInfo info;
    for (const auto& [field, member] : fields_)
        info.*member = field->text();
    for (int row = 0; row < revisions_->rowCount(); ++row)
        info.revisions.push_back({cell(revisions_, row, 0).toStdString(),
                                  cell(revisions_, row, 1).toStdString(),
                                  cell(revisions_, row, 2).toStdString()});
    return info;
}

bool ProjectInfoPanel::editInDialog(QWidget* parent, ProjectInfo& info) {
    QDialog dialog(parent);
    dialog.setWindowTitle(tr("Project information"));
    auto* layout = new QVBoxLayout(&dialog);
    auto* panel = new ProjectInfoPanel;
    panel->setInfo(info);
    layout->addWidget(panel);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    layout->addWidget(buttons);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, [&dialog, panel] {
        const QString e = panel->problem();
        if (e.isEmpty()) return dialog.accept();
        QMessageBox::warning(&dialog, tr("Project information"), e);
    });
    dialog.resize(560, 520);
    if (dialog.exec() != QDialog::Accepted) return false;
    info = panel->info();
    return true;
}

} // namespace kinstab::ui
