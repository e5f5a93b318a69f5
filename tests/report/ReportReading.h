// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the report tests share: small analyses for reports read as words, and reading a written
// report back with poppler's pdftotext (poppler-utils).

#include "report/ReportAnalysis.h"

#include <QProcess>
#include <QString>

#include <utility>

// Small figure grids, no solver cross-check: the tests read words and the tabled numbers.
inline kinstab::report::AnalysisOptions quickAnalysis() {
    kinstab::report::AnalysisOptions o;
    o.figureGrid = 7;
    o.planarFigureGrid = 5;
    o.sliceStep = 0.05;
    o.crossCheck = false;
    return o;
}

// Pages first..last as laid out text; "" when pdftotext fails.
inline QString pdfText(const QString& pdf, int first = 1, int last = 999) {
    QProcess p;
    p.start("pdftotext",
            {"-layout", "-f", QString::number(first), "-l", QString::number(last), pdf, "-"});
    p.waitForFinished(60000);
    return QString::fromUtf8(p.readAllStandardOutput());
}

// One line of words, with the ligatures poppler keeps from the PDF's fonts spelled out.
inline QString flat(QString s) {
    const std::pair<const char*, const char*> ligatures[] = {
        {"ﬃ", "ffi"}, {"ﬄ", "ffl"}, {"ﬀ", "ff"}, {"ﬁ", "fi"}, {"ﬂ", "fl"}};
    for (const auto& [from, to] : ligatures)
        s.replace(QString::fromUtf8(from), QLatin1String(to));
    return s.simplified();
}

inline bool havePdfToText() {
    QProcess v;
    v.start("pdftotext", {"-v"});
    return v.waitForFinished(10000) && v.exitCode() == 0;
}
