// SPDX-License-Identifier: GPL-3.0-or-later
// The model's names, written once in core/base/ModelKind.h: the "model" of project files and
// --model of kinstab-cli (docs/man/kinstab-cli.1.in), both ways; no other text is a model.

#include "core/base/ModelKind.h"

#include <QtTest>

using namespace kinstab;

class TestModelKind : public QObject {
    Q_OBJECT
private slots:
    void namesAreTheFileFormats() {
        QCOMPARE(std::string(modelKindName(ModelKind::Slab1D)), std::string("slab1d"));
        QCOMPARE(std::string(modelKindName(ModelKind::Planar)), std::string("planar"));
        QCOMPARE(modelKindChoices(), std::string("slab1d or planar"));
    }

    void everyKindRoundTrips() {
        for (ModelKind m : kModelKinds)
            QCOMPARE(modelKindFromName(modelKindName(m)), m);
    }

    void otherTextIsNoModel() {
        for (const char* t : {"", "Planar", "slab1D", "2dof", "planar ", "slab1d\n"})
            QVERIFY2(!modelKindFromName(t), t);
    }
};

QTEST_GUILESS_MAIN(TestModelKind)
#include "tst_model_kind.moc"
