// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/NumberField.h"

#include "ui/FieldError.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QVBoxLayout>

#include <cmath>

namespace kinstab::ui {

NumberField::NumberField(const QString& unit, QWidget* parent)
    : QWidget(parent), m_edit(new QLineEdit(this)), m_unit(new QLabel(unit, this)),
      m_errorLabel(new QLabel(this)) {
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(1);
    auto* row = new QHBoxLayout;
    row->setSpacing(4);
    row->addWidget(m_edit, 1);
    row->addWidget(m_unit);
    column->addLayout(row);
    styleFieldError(m_errorLabel);
    column->addWidget(m_errorLabel);
    m_edit->setMinimumWidth(60);
    connect(m_edit, &QLineEdit::textChanged, this, [this] {
        revalidate();
        if (!m_rendering) emit edited();
    });
}

void NumberField::setCheck(Check check) {
    m_check = std::move(check);
    revalidate();
}

void NumberField::setOptional(const QString& placeholder) {
    m_optional = true;
    m_edit->setPlaceholderText(placeholder);
    revalidate();
}

void NumberField::setOptionalValue(std::optional<double> v) {
    if (v)
        setValue(*v);
    else
        m_edit->clear();
}

bool NumberField::isEmpty() const {
    return m_edit->text().trimmed().isEmpty();
}

void NumberField::setValue(double v) {
    m_exact = v;
    render();
}

double NumberField::storedPerShown() const {
    if (!m_length) return 1.0;
    return metresPerDisplayUnit(m_system, *m_length) / m_metresPerStored;
}

void NumberField::render() {
    const double k = storedPerShown();
    // Ten digits in the stored unit; after a conversion, to the millimetre or 0.01 in/ft
    // (core/base/UnitSystem.h: 53.95 m, not 53.9496). The exact stored value comes back from
    // value() while the text is not edited.
    m_rendered =
        k == 1.0
            ? QString::number(*m_exact, 'g', 10)
            : QString::fromStdString(lengthText(*m_exact * m_metresPerStored, m_system, *m_length));
    m_edit->setText(m_rendered);
}

void NumberField::setLength(LengthScale scale, double metresPerStored) {
    const std::optional<double> v = value();
    m_length = scale;
    m_metresPerStored = metresPerStored;
    m_unit->setText(lengthSymbol(m_system, scale));
    if (v) setValue(*v);
}

void NumberField::setUnitSystem(UnitSystem s) {
    if (s == m_system) return;
    const std::optional<double> v = value();
    m_system = s;
    if (!m_length) return;
    m_unit->setText(lengthSymbol(s, *m_length));
    if (!v) return; // an invalid entry stays as typed
    m_rendering = true;
    m_exact = v;
    render();
    m_rendering = false;
}

QString NumberField::storedSymbol() const {
    for (UnitSystem s : {UnitSystem::SI, UnitSystem::US})
        for (LengthScale l : {LengthScale::Structure, LengthScale::Detail})
            if (metresPerDisplayUnit(s, l) == m_metresPerStored) return lengthSymbol(s, l);
    return QStringLiteral("× %1 m").arg(m_metresPerStored);
}

QString NumberField::text() const {
    return m_edit->text();
}

void NumberField::setUnit(const QString& unit) {
    m_unit->setText(unit);
}

// "1.5" always, and "1,5" where the user's locale writes a decimal comma.
double NumberField::parse(const QString& text, bool* ok) {
    const double v = text.toDouble(ok);
    return *ok ? v : QLocale().toDouble(text, ok);
}

std::optional<double> NumberField::value() const {
    bool ok = false;
    const double v = parse(m_edit->text().trimmed(), &ok);
    if (!ok || !std::isfinite(v) || !m_error.isEmpty()) return std::nullopt;
    if (m_exact && m_edit->text() == m_rendered) return *m_exact;
    return v * storedPerShown();
}

void NumberField::setFieldToolTip(const QString& tip) {
    m_edit->setToolTip(tip);
}

void NumberField::revalidate() {
    const QString text = m_edit->text().trimmed();
    bool ok = false;
    const double v = parse(text, &ok);
    QString error;
    if (text.isEmpty())
        error = m_optional ? QString() : tr("required");
    else if (!ok || !std::isfinite(v))
        error = tr("\"%1\" is not a number").arg(text);
    else if (m_check) {
        const double stored =
            m_exact && m_edit->text() == m_rendered ? *m_exact : v * storedPerShown();
        error = m_check(stored);
        // The check's limits are in the stored unit: say what the entry is in it.
        if (!error.isEmpty() && storedPerShown() != 1.0)
            error += tr(" (%1 %2 = %3 %4)")
                         .arg(text, m_unit->text())
                         .arg(stored, 0, 'g', 6)
                         .arg(storedSymbol());
    }
    if (showFieldError(error, m_error, m_errorLabel, m_edit)) emit validityChanged();
}

NumberField::Check positiveCheck() {
    return
        [](double v) { return v > 0 ? QString() : NumberField::tr("must be > 0 (got %1)").arg(v); };
}

NumberField::Check rangeCheck(double lo, double hi, bool loInclusive) {
    return [=](double v) {
        const bool okLo = loInclusive ? v >= lo : v > lo;
        if (okLo && v <= hi) return QString();
        return NumberField::tr("must be %1 %2 and ≤ %3 (got %4)")
            .arg(loInclusive ? "≥" : ">")
            .arg(lo)
            .arg(hi)
            .arg(v);
    };
}

NumberField::Check rangeCheck(Range r) {
    return rangeCheck(r.lo, r.hi, !r.loOpen);
}

} // namespace kinstab::ui
