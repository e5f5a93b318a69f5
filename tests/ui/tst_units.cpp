// SPDX-License-Identifier: GPL-3.0-or-later
// One unit system for the whole window (View → Units, issue #18): every length field shows SI
// or US customary lengths, switching re-shows the same values (1 ft = 0.3048 m and
// 1 in = 25.4 mm exactly, by the 1959 international yard and pound agreement), the choice is
// remembered, and the project the window saves is the same byte for byte in either system.

#include "WindowFields.h"
#include "core/io/Project.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"
#include "ui/Units.h"
#include "ui/teaching/ParameterPanel.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QStandardPaths>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;
using kinstab::testing::namedField;

namespace {
QString unitLabel(NumberField* f) {
    QString last;
    for (QLabel* l : f->findChildren<QLabel*>())
        if (l->isVisibleTo(f) && !l->text().isEmpty()) last = l->text();
    return last; // the unit label follows the line edit; the error label is hidden
}
void choose(MainWindow& w, const char* action) {
    auto* a = w.findChild<QAction*>(QString::fromLatin1(action));
    QVERIFY(a);
    a->trigger();
}
std::string saved(const MainWindow& w) {
    return projectToJson(w.project()).dump(2);
}
} // namespace

class TstUnits : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void fieldFollowsTheUnitSystem() {
        NumberField f;
        f.setLength(LengthScale::Structure, 0.3048); // stored in feet, like a project's
        f.setValue(10.0);
        f.setUnitSystem(UnitSystem::US);
        QCOMPARE(f.text(), QStringLiteral("10"));
        f.setUnitSystem(UnitSystem::SI);
        QCOMPARE(f.text(), QStringLiteral("3.048")); // 10 × 0.3048 m
        QCOMPARE(unitLabel(&f), QStringLiteral("m"));
        QCOMPARE(*f.value(), 10.0); // exactly what was set, not 3.048 / 0.3048
        f.setUnitSystem(UnitSystem::US);
        QCOMPARE(f.text(), QStringLiteral("10"));
        QCOMPARE(unitLabel(&f), QStringLiteral("ft"));
    }

    void typedValueIsConverted() {
        NumberField f;
        f.setLength(LengthScale::Detail, 1.0); // stored in metres, shown in mm or in
        f.setUnitSystem(UnitSystem::US);
        f.lineEdit()->setText(QStringLiteral("7.625")); // the paper's 8-inch block wall
        QCOMPARE_LE(std::abs(*f.value() - 0.193675), 1e-15);
        f.setUnitSystem(UnitSystem::SI);
        QCOMPARE(f.text(), QStringLiteral("193.675"));
        QCOMPARE(unitLabel(&f), QStringLiteral("mm"));
    }

    void rangeErrorSaysTheStoredValue() {
        NumberField f;
        f.setLength(LengthScale::Structure, 0.3048);
        f.setCheck(rangeCheck(0, 3000, false));
        f.setUnitSystem(UnitSystem::SI);
        f.lineEdit()->setText(QStringLiteral("-3.048"));
        QVERIFY(!f.isValid());
        QVERIFY2(f.error().contains(QStringLiteral("-3.048 m = -10 ft")), qPrintable(f.error()));
    }

    void windowSwitchesEveryLengthAndSavesTheSameProject() {
        MainWindow w;
        choose(w, "unitsUS");
        NumberField* height = namedField(&w, "height");
        NumberField* width = namedField(&w, "wallWidth");
        QCOMPARE(height->text(), QStringLiteral("177")); // the paper's building, h_n in ft
        QCOMPARE(width->text(), QStringLiteral("7.625"));
        QCOMPARE(unitLabel(width), QStringLiteral("in"));
        const std::string us = saved(w);
        choose(w, "unitsSI");
        QCOMPARE(height->text(), QStringLiteral("53.9496")); // 177 × 0.3048
        QCOMPARE(unitLabel(height), QStringLiteral("m"));
        QCOMPARE(unitLabel(namedField(&w, "planDimension")), QStringLiteral("m"));
        QCOMPARE(width->text(), QStringLiteral("193.675")); // 7.625 × 25.4
        QCOMPARE(unitLabel(width), QStringLiteral("mm"));
        QCOMPARE(saved(w), us);
        QCOMPARE(savedUnitSystem(), UnitSystem::SI);
        choose(w, "unitsUS");
        QCOMPARE(saved(w), us);
        QCOMPARE(savedUnitSystem(), UnitSystem::US);
        MainWindow next; // the next start shows the remembered system
        QCOMPARE(unitLabel(namedField(&next, "height")), QStringLiteral("ft"));
    }

    // The Teaching view's wall width follows too, and its run keeps the exact width.
    void teachingFollows() {
        MainWindow w;
        TeachingView* view = w.teachingView();
        const double d = view->params().wallWidthM;
        QDoubleSpinBox* spin = view->parameterPanel()->spinBox(ParameterPanel::Quantity::WallWidth);
        choose(w, "unitsUS");
        QCOMPARE(spin->suffix(), QStringLiteral(" in"));
        QCOMPARE_LE(std::abs(spin->value() - d / 0.0254), 0.0005 + 1e-12); // 3 decimals shown
        choose(w, "unitsSI");
        QCOMPARE(spin->suffix(), QStringLiteral(" mm"));
        QCOMPARE_LE(std::abs(spin->value() - d * 1000), 0.05 + 1e-12); // 1 decimal shown
        QCOMPARE(view->params().wallWidthM, d);
    }
};

QTEST_MAIN(TstUnits)
#include "tst_units.moc"
