// SPDX-License-Identifier: GPL-3.0-or-later
// The Codes panel names each code as the catalogue does (core/codes/CodeCatalog.h): one group per
// code, in catalogue order, titled with the catalogue's title, so the panel, the verdict table,
// the charts and the report cannot drift apart again.

#include "core/codes/CodeCatalog.h"
#include "core/codes/CodeSet.h"
#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/NumberField.h"
#include "ui/VerdictPanel.h"

#include <functional>

#include <QGroupBox>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {
QString text(std::string_view s) {
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}
} // namespace

class TestCodesPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void groupsAreTitledFromTheCatalogue() {
        CodesPanel panel;
        const QList<QGroupBox*> groups = panel.findChildren<QGroupBox*>();
        QCOMPARE(groups.size(), qsizetype(codeCatalog().size()));
        for (std::size_t i = 0; i < codeCatalog().size(); ++i)
            QCOMPARE(groups[qsizetype(i)]->title(), text(codeCatalog()[i].title));
    }

    // The panels' default building and codes: each verdict row reads the catalogue's
    // short name, the full title is its tooltip.
    void verdictRowsUseTheShortNames() {
        BuildingPanel building;
        CodesPanel codes;
        VerdictPanel verdicts;
        const std::vector<CodeResult> results = runCodes(building.building(), codes.codes());
        QVERIFY(!results.empty());
        verdicts.setCodeResults(results);
        QCOMPARE(verdicts.rowCount(), int(results.size()));
        for (int row = 0; row < int(results.size()); ++row) {
            const CodeInfo* info = findCode(results[std::size_t(row)].code);
            QVERIFY(info);
            QCOMPARE(verdicts.codeText(row), text(info->shortName));
        }
    }

    // A field accepts exactly what the code's validator accepts: each limit is written once, in
    // the code's header. The values sit just inside and just outside the validators' ranges
    // (UBC 1976 K 0.67-2.5, UBC 1997 I 1-1.25, ASCE 7 T_L > 0, EN 1998-1 q 1-8, UBC 1976 T_s > 0);
    // before the limits were shared the panel accepted K = 2.6, I = 1.3, q = 8.5 and refused
    // T_L = 0.5.
    void fieldsAcceptWhatTheValidatorAccepts() {
        struct Row {
            const char* field;
            double value;
            std::function<void(CodeSelection&, double)> set;
        };
        const std::vector<Row> rows = {
            {"ubc76K", 2.5, [](CodeSelection& c, double v) { c.ubc1976->k = v; }},
            {"ubc76K", 2.6, [](CodeSelection& c, double v) { c.ubc1976->k = v; }},
            {"ubc76Ts", 0.0, [](CodeSelection& c, double v) { c.ubc1976->sitePeriod = v; }},
            {"ubc76Ts", 10.0, [](CodeSelection& c, double v) { c.ubc1976->sitePeriod = v; }},
            {"ubc97I", 1.25, [](CodeSelection& c, double v) { c.ubc1997->importance = v; }},
            {"ubc97I", 1.3, [](CodeSelection& c, double v) { c.ubc1997->importance = v; }},
            {"asceTl", 0.5, [](CodeSelection& c, double v) { c.asce7_22->tl = v; }},
            {"asceTl", 0.0, [](CodeSelection& c, double v) { c.asce7_22->tl = v; }},
            {"ec8Q", 8.0, [](CodeSelection& c, double v) { c.ec8->q = v; }},
            {"ec8Q", 8.5, [](CodeSelection& c, double v) { c.ec8->q = v; }},
        };
        CodeSelection all;
        all.ubc1976 = Ubc1976Inputs{};
        all.ubc1997 = Ubc1997Inputs{};
        all.asce7_22 = Asce7Inputs{};
        all.ec8 = Eurocode8Inputs{};
        QVERIFY(validateCodes(all).empty());
        CodesPanel panel;
        for (const Row& r : rows) {
            auto* field = panel.findChild<NumberField*>(QString::fromLatin1(r.field));
            QVERIFY2(field, r.field);
            field->setValue(r.value);
            CodeSelection c = all;
            r.set(c, r.value);
            const bool coreAccepts = validateCodes(c).empty();
            QVERIFY2(field->isValid() == coreAccepts,
                     qPrintable(QStringLiteral("%1 = %2").arg(r.field).arg(r.value)));
        }
    }
};

QTEST_MAIN(TestCodesPanel)
#include "tst_codes_panel.moc"
