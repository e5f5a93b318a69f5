// SPDX-License-Identifier: GPL-3.0-or-later
// Grid lists ("0.70:1.15:0.05", "a,b,c") read the same under a German locale, where the C
// library's decimal separator is ',' — the GUI sets the user's locale, and a project's grid
// must still open (the example projects failed to open under de_DE before).

#include "core/sweep/Grid.h"

#include <QtTest>

#include <clocale>
#include <string>

class TestGridLocale : public QObject {
    Q_OBJECT
private:
    std::string saved_;
private slots:
    void init() {
        saved_ = std::setlocale(LC_ALL, nullptr);
        if (!std::setlocale(LC_ALL, "de_DE.UTF-8") && !std::setlocale(LC_ALL, "de_DE.utf8"))
            QSKIP("locale de_DE.UTF-8 is not installed");
    }
    void cleanup() { std::setlocale(LC_ALL, saved_.c_str()); }

    void rangeUnderGermanLocale() {
        // The example project's grid: 0.70 to 1.15 in steps of 0.05 is 10 values.
        const kinstab::ParsedList p = kinstab::parseList("0.70:1.15:0.05");
        QVERIFY2(p.error.empty(), p.error.c_str());
        QCOMPARE(p.values.size(), std::size_t(10));
        QCOMPARE(p.values.front(), 0.70);
        QCOMPARE_LT(std::abs(p.values.back() - 1.15), 1e-12);
    }
    void listUnderGermanLocale() {
        const kinstab::ParsedList p = kinstab::parseList("0.5, +1.25,2e-1");
        QVERIFY2(p.error.empty(), p.error.c_str());
        QCOMPARE(p.values, std::vector<double>({0.5, 1.25, 0.2}));
    }
    void badNumbersStayBad() {
        // A German-style "0,7" is two list items, and text or "+-1" is no number at all.
        QCOMPARE(kinstab::parseList("0,7").values.size(), std::size_t(2));
        for (const char* bad : {"abc", "+-1", "1.5x", "nan", "inf", "1:2:"})
            QVERIFY2(!kinstab::parseList(bad).error.empty(), bad);
    }
};

QTEST_GUILESS_MAIN(TestGridLocale)
#include "tst_grid_locale.moc"
