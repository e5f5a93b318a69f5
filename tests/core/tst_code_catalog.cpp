// SPDX-License-Identifier: GPL-3.0-or-later
// The code catalogue is the one place a code's key, name and clause are written: every code
// function must label its result from it, in the catalogue's order.

#include "core/codes/CodeCatalog.h"
#include "core/codes/CodeSet.h"

#include <QtTest>

using namespace kinstab;

class TestCodeCatalog : public QObject {
    Q_OBJECT
private slots:
    void resultsAreLabelledFromTheCatalogue() {
        // The paper's building with every code selected at its defaults (docs/codes.md).
        CodeSelection all;
        all.ubc1976 = Ubc1976Inputs{};
        all.atc306 = Atc306Inputs{};
        all.ubc1997 = Ubc1997Inputs{};
        all.asce7_22 = Asce7Inputs{};
        all.ec8 = Eurocode8Inputs{};
        const std::vector<CodeResult> results = runCodes(Building{}, all);
        const auto catalog = codeCatalog();
        QCOMPARE(results.size(), catalog.size());
        for (std::size_t k = 0; k < results.size(); ++k) {
            QCOMPARE(results[k].code, std::string(catalog[k].id));
            QCOMPARE(results[k].title, std::string(catalog[k].title));
            QVERIFY(isSelected(all, catalog[k].id));
            QCOMPARE(static_cast<std::size_t>(catalog[k].key), k);
            QCOMPARE(&codeInfo(catalog[k].key), &catalog[k]);
        }
        QCOMPARE(codeKeys().size(), catalog.size());
    }
    void unknownKeys() {
        QVERIFY(findCode("ubc1988") == nullptr);
        QVERIFY(!isSelected(CodeSelection{}, "ubc1976"));
    }
    void coloursDiffer() {
        const auto catalog = codeCatalog();
        for (std::size_t i = 0; i < catalog.size(); ++i)
            for (std::size_t j = i + 1; j < catalog.size(); ++j)
                QVERIFY(catalog[i].rgb != catalog[j].rgb);
    }
};

QTEST_APPLESS_MAIN(TestCodeCatalog)
#include "tst_code_catalog.moc"
