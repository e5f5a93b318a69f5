// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A number input with its check: the reason it is invalid is shown beside the field, so the
// engineer sees what to fix without pressing Run first.

#include "core/base/Range.h"
#include "ui/Units.h"

#include <QWidget>

#include <functional>
#include <optional>

class QLabel;
class QLineEdit;

namespace kinstab::ui {

class NumberField : public QWidget {
    Q_OBJECT
public:
    // Returns an empty string when the value is acceptable, else the reason (shown in red).
    using Check = std::function<QString(double)>;

    explicit NumberField(const QString& unit = {}, QWidget* parent = nullptr);

    void setCheck(Check check);
    // An optional field may be left empty (value() is then nullopt and the field is valid);
    // the placeholder says what empty means ("from the occupancy").
    void setOptional(const QString& placeholder);
    void setOptionalValue(std::optional<double> v);
    bool isEmpty() const;
    void setValue(double v);
    void setUnit(const QString& unit);
    std::optional<double> value() const; // nullopt when the text is not an acceptable number
    // A length: value() and setValue() keep the stored unit (metresPerStored metres, e.g. the
    // project file's ft or m), the field shows it in the unit system's unit. A value shown in
    // another unit and not edited comes back exactly as it was set.
    void setLength(LengthScale scale, double metresPerStored);
    void setUnitSystem(UnitSystem s); // re-shows the value; no edited() signal
    UnitSystem unitSystem() const { return m_system; }
    QString text() const; // as shown
    bool isValid() const { return m_error.isEmpty(); }
    QString error() const { return m_error; }
    QLineEdit* lineEdit() const { return m_edit; }
    void setFieldToolTip(const QString& tip);
    // Re-run the check (e.g. when a field it depends on changed).
    void revalidate();

signals:
    void edited();          // the text changed (valid or not)
    void validityChanged(); // isValid() may have changed

private:
    static double parse(const QString& text, bool* ok);
    double storedPerShown() const; // 1 unless a length shown in another unit
    void render();                 // m_exact into the line edit, in the shown unit
    QString storedSymbol() const;  // "ft", "m", "in" or "mm"

    QLineEdit* m_edit;
    QLabel* m_unit;
    QLabel* m_errorLabel;
    Check m_check;
    QString m_error;
    bool m_optional = false;
    std::optional<LengthScale> m_length;
    double m_metresPerStored = 1.0;
    UnitSystem m_system = UnitSystem::SI;
    std::optional<double> m_exact; // the stored value last set, while its text is unchanged
    QString m_rendered;
    bool m_rendering = false;
};

// Common checks, with the reason phrased for the engineer.
NumberField::Check positiveCheck();
NumberField::Check rangeCheck(double lo, double hi, bool loInclusive = true);
NumberField::Check rangeCheck(Range r); // a range a validator in core checks

} // namespace kinstab::ui
