// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/Units.h"

#include <QCoreApplication>
#include <QSettings>

namespace kinstab::ui {

namespace {
const char* const kKey = "view/unitSystem";
} // namespace

double metresPerDisplayUnit(UnitSystem s, LengthScale scale) {
    return metresPerUnit(s, scale);
}

QString lengthSymbol(UnitSystem s, LengthScale scale) {
    return QString::fromStdString(lengthUnitSymbol(s, scale));
}

QString unitSystemTitle(UnitSystem s) {
    return s == UnitSystem::US ? QCoreApplication::translate("Units", "US customary (ft, in)")
                               : QCoreApplication::translate("Units", "SI (m, mm)");
}

UnitSystem savedUnitSystem() {
    return QSettings().value(kKey).toString() == QLatin1String("US") ? UnitSystem::US
                                                                     : UnitSystem::SI;
}

void saveUnitSystem(UnitSystem s) {
    QSettings().setValue(kKey, s == UnitSystem::US ? QStringLiteral("US") : QStringLiteral("SI"));
}

} // namespace kinstab::ui
