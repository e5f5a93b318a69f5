// SPDX-License-Identifier: GPL-3.0-or-later
// The slab, model and grid panels accept exactly what the run's validators accept: each limit
// is written once in core (core/slab/SlabInputs.h, core/base/InputLimits.h,
// core/excitation/FrequencyRange.h). The values sit just inside and just outside those ranges;
// before the limits were shared the panels refused mu = 0 and A = 500 g, which a run accepts.

#include "core/slab/SlabModel2D.h"
#include "core/slab/SlabTypes.h"
#include "core/sweep/Grid.h"
#include "ui/GridPanel.h"
#include "ui/ModelPanel.h"
#include "ui/NumberField.h"
#include "ui/SlabPanel.h"

#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {
// Sets the field to v and compares its verdict with the validator's.
void agree(QWidget& panel, const char* name, double v, bool coreAccepts) {
    auto* field = panel.findChild<NumberField*>(QString::fromLatin1(name));
    QVERIFY2(field, name);
    field->setValue(v);
    QVERIFY2(field->isValid() == coreAccepts,
             qPrintable(QStringLiteral("%1 = %2 (core %3)").arg(name).arg(v).arg(coreAccepts)));
}

bool slabAccepts(double mu, double limit) {
    return validateSlabParams(SlabParams{mu, limit, std::nullopt}).empty();
}

bool gridAccepts(double amplitude, double frequency) {
    return validateGrid(SweepGrid{{amplitude}, {frequency}}).empty();
}
} // namespace

class TestSlabPanelLimits : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void slabFields() {
        SlabPanel panel;
        for (double mu : {0.0, 0.005, 0.01, 10.0, 10.5, -0.1})
            agree(panel, "mu", mu, slabAccepts(mu, 1.0));
        for (double limit : {0.0, 1e-4, 1e-3, 1e6, 2e6})
            agree(panel, "limit", limit, slabAccepts(0.6, limit));
        // mu = 0.005 is below the slipperiest bearing (core/slab/SlabInputs.h): refused by both.
        QVERIFY(!slabAccepts(0.005, 1.0));
        QVERIFY(slabAccepts(0.01, 1.0));
    }

    void modelFields() {
        ModelPanel panel;
        for (double theta : {0.0, 20.0, 1e6, 2e6}) {
            PlanarParams p;
            p.theta = theta;
            agree(panel, "theta", theta, validatePlanarParams(p).empty());
        }
    }

    void gridFields() {
        GridPanel panel;
        for (double a : {0.0, 500.0, 1000.0, 1001.0})
            agree(panel, "aFrom", a, gridAccepts(a, 1.0));
        for (double f : {1e-4, 1e-3, 1000.0, 1001.0})
            agree(panel, "fFrom", f, gridAccepts(1.0, f));
        QVERIFY(gridAccepts(500.0, 1.0)); // the row that used to disagree
    }
};

QTEST_MAIN(TestSlabPanelLimits)
#include "tst_slab_panel_limits.moc"
