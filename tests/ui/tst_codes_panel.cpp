// SPDX-License-Identifier: GPL-3.0-or-later
// The Codes panel names each code as the catalogue does (core/codes/CodeCatalog.h): one group per
// code, in catalogue order, titled with the catalogue's title, so the panel, the verdict table,
// the charts and the report cannot drift apart again.

#include "core/codes/CodeCatalog.h"
#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/VerdictPanel.h"

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
};

QTEST_MAIN(TestCodesPanel)
#include "tst_codes_panel.moc"
