// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/InputPanel.h"

#include "ui/NumberField.h"

#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>

namespace kinstab::ui {

InputPanel::InputPanel(QWidget* parent) : QWidget(parent), m_form(new QFormLayout(this)) {
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_form->setLabelAlignment(Qt::AlignRight | Qt::AlignTop);
}

NumberField* InputPanel::addField(const QString& name, const QString& label, const QString& unit,
                                  const QString& toolTip) {
    auto* field = new NumberField(unit, this);
    field->setObjectName(name);
    field->setFieldToolTip(toolTip);
    auto* l = new QLabel(label, this);
    l->setToolTip(toolTip);
    l->setBuddy(field->lineEdit());
    m_form->addRow(l, field);
    track(field, label);
    return field;
}

void InputPanel::track(NumberField* field, const QString& label) {
    m_fields.emplace_back(field, label);
    connect(field, &NumberField::edited, this, &InputPanel::changed);
    connect(field, &NumberField::validityChanged, this, &InputPanel::changed);
}

bool InputPanel::fieldsValid() const {
    for (const auto& [field, label] : m_fields)
        if (field->isEnabled() && !field->isValid()) return false;
    return true;
}

bool InputPanel::isValid() const {
    return fieldsValid() && extraProblems().isEmpty();
}

QStringList InputPanel::problems() const {
    QStringList out;
    for (const auto& [field, label] : m_fields)
        if (field->isEnabled() && !field->isValid()) {
            QString name = label;
            name.remove(QLatin1Char('&'));
            if (name.endsWith(QLatin1Char(':'))) name.chop(1);
            out << QStringLiteral("%1: %2").arg(name, field->error());
        }
    return out + extraProblems();
}

} // namespace kinstab::ui
