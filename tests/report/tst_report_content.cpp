// SPDX-License-Identifier: GPL-3.0-or-later
// What an engineer signs and an official accepts (issue 17), read back from the PDF with
// pdftotext: the project's metadata on the title block, signature block and revision table; the
// assumptions that apply to the project and no other; the acceptance criterion in words; plain
// labels instead of the project file's keys; the verdict once; the sections the user chose.

#include "core/io/Project.h"
#include "report/ReportWriter.h"
#include "report/SectionCatalog.h"

#include "ReportReading.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::report;

namespace {

const std::string kExamples = KINSTAB_SOURCE_DIR "/resources/examples/";

} // namespace

class TestReportContent : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // The whole report of an example project as one line of words.
    QString reportText(const Project& p, const SectionSet& sections, int* pages = nullptr) {
        ReportSource s{p, "example.json", {}};
        s.sections = sections;
        const QString pdf = dir_.filePath("report.pdf");
        const int n = writeReport(s, computeReportAnalysis(p, quickAnalysis()), pdf, PaperSize::A4);
        if (pages) *pages = n;
        return flat(pdfText(pdf));
    }

private slots:
    void initTestCase() {
        if (!havePdfToText()) QSKIP("pdftotext not installed");
    }

    // resources/examples/paper-16-story.json's "info": every field on page 1.
    void metadataOnTheTitleBlock() {
        const Project p = loadProject(kExamples + "paper-16-story.json");
        ReportSource s{p, "paper-16-story.json", {}};
        const QString pdf = dir_.filePath("meta.pdf");
        writeReport(s, computeReportAnalysis(p, quickAnalysis()), pdf, PaperSize::A4);
        const QString page1 = flat(pdfText(pdf, 1, 1));
        for (const char* field :
             {"Project no. EX-1980-016", "Client Example Property Owner LLC (example client)",
              "Site 100 Example Avenue, Los Angeles, CA 90000",
              "Engineer A. N. Example, P.E. (example), reg. no. S 00000 (example)",
              "Firm Example Structural Engineers (example firm)",
              "Prepared by A. N. Example, checked by B. C. Checker", "Revision A, 2026-11-24"})
            QVERIFY2(page1.contains(QString::fromUtf8(field)), field);
        // The revision table lists every revision; the signature block has room to sign.
        QVERIFY(page1.contains("0 2026-11-02 Issued for review (example)"));
        QVERIFY(page1.contains("A 2026-11-24 Issued for permit (example)"));
        QCOMPARE(page1.count("signature"), 3);
        QVERIFY(page1.contains("seal"));
    }

    // The 1-DOF sine project: the 1-DOF limits, no record and no planar ones.
    void assumptionsOfTheSineProject() {
        const QString text =
            reportText(loadProject(kExamples + "paper-16-story.json"), defaultSections());
        QVERIFY(text.contains("Assumptions and limitations"));
        QVERIFY(text.contains("The slab and the walls are rigid"));
        QVERIFY(text.contains("one constant coefficient μ = 0.600"));
        QVERIFY(text.contains("idealized as an enveloped sine (moderate envelope) at the building "
                              "frequency f = 1/T"));
        QVERIFY(text.contains("read as the peak acceleration (in g) of the top floor"));
        QVERIFY(text.contains("no motion along the walls and no vertical motion"));
        QVERIFY(!text.contains("RSN68"));
        QVERIFY(!text.contains("floor filter"));
    }

    // The planar project (gravity only) and the record project name their own.
    void assumptionsFollowTheProject() {
        const QString planar =
            reportText(loadProject(kExamples + "paper-planar.json"), {"assumptions"});
        QVERIFY(planar.contains("moves the slab in both horizontal directions"));
        QVERIFY(planar.contains("No vertical motion is applied (gravity only)."));
        QVERIFY(!planar.contains("no motion along the walls"));
        const QString record =
            reportText(loadProject(kExamples + "paper-16-story-record.json"), {"assumptions"});
        QVERIFY(record.contains("through a single-mode floor filter (T = 1.000 s, ζ = 0.020)"));
        // The record project's assessment has the enveloped sine's checks beside the record's
        // (core/assessment): both idealizations are assumptions of it.
        QVERIFY(record.contains("idealized as an enveloped sine"));
    }

    void acceptanceCriterionInWords() {
        const QString text = reportText(loadProject(kExamples + "paper-16-story.json"), {});
        QVERIFY(text.contains("Acceptance criterion: every check's margin must exceed 1"));
        QVERIFY(text.contains("margin = critical floor peak / (F_top/w_top)"));
        QVERIFY(text.contains("above 1 the structure reaches its code strength"));
        QVERIFY(text.contains("below 1 the slab slides off"));
        QVERIFY(text.contains("The assessment does not cover"));
        QVERIFY(!text.contains("for the floor checks")); // no floor checks in this project
        QVERIFY(text.contains("must be checked by a qualified engineer"));
    }

    // No key of the project file reaches the reader; the wall width stands beside t*. The checks'
    // ids (sine.asce7_22, ...) are the one exception: they name each check as `kinstab-cli
    // check` and kinstab.assess do, so that a reader can find it there.
    void plainLabelsOnly() {
        const QRegularExpression checkId("\\b(sine|planar|record|floors)\\.[a-z0-9_.]+");
        for (const char* f : {"paper-16-story.json", "paper-16-story-record.json",
                              "paper-planar.json", "paper-16-story-study.json"}) {
            const QString text =
                reportText(loadProject(kExamples + f), allSections()).remove(checkId);
            for (const char* key : {"asce7_22", "ubc1976", "atc306", "dual_frame_wall", "= default",
                                    "tau_max", "site_class", "risk_category"})
                QVERIFY2(!text.contains(QString::fromUtf8(key)),
                         (std::string(f) + ": " + key).c_str());
            QVERIFY2(text.contains("dual system: moment frame with shear walls"), f);
            QVERIFY2(text.contains("design spectral acceleration, short periods S_DS 1 g"), f);
            // t* = 0.099 s: d = 2 g t*² = 0.19223 m = 7.568 in (the paper's nominal 8-inch
            // wall), to 0.01 in in the project's US units (a building in ft).
            QVERIFY2(text.contains("wall width (from t*: d = 2g·t*²) d 7.57 in"), f);
        }
    }

    // Issue 35: per parameter set, the statistics of the critical intensity over the records
    // that collapse. Independent calculation (NumPy on resources/examples/study-example.jsonl,
    // the risk example's results): x = critical_im_g of the set's rows; set 1 (mu 0.4): 6
    // collapses, mean 1.2653776, median 1.1449609, std (ddof 1) 0.5134675, mean ln 0.1630646,
    // std ln 0.4238016; set 2 (mu 0.6): 1.5764062, 1.5005859, 0.5150435, 0.4076314, 0.3450679.
    void studyStatisticsPerSet() {
        const QString text =
            reportText(loadProject(kExamples + "paper-16-story-risk.json"), allSections());
        QVERIFY(text.contains("Critical intensity per parameter set"));
        QVERIFY2(text.contains("1 6 0 1.265 1.145 0.513 0.163 0.424"), qPrintable(text));
        QVERIFY(text.contains("2 6 0 1.576 1.501 0.515 0.408 0.345"));
    }

    // Each check's verdict appears once, on page 1; the check section refers to it.
    void verdictOnce() {
        const QString text =
            reportText(loadProject(kExamples + "paper-16-story.json"), defaultSections());
        const Project p = loadProject(kExamples + "paper-16-story.json");
        const ReportAnalysis a = computeReportAnalysis(p, quickAnalysis());
        QCOMPARE(a.check.codes.size(), std::size_t(4));
        for (const CodeVerdict& v : a.check.codes) // each row once: "... 0.979 4.26 overstress"
            QCOMPARE(text.count(QString::number(*v.margin, 'f', 2) + " overstress governs"), 1);
        QVERIFY(text.contains("checks of the assessment on page 1"));
        QCOMPARE(text.count("ATC 3-06 (1978) §4.2: "), 0); // no per-code verdict sentences
    }

    void sectionsAreChosen() {
        const Project p = loadProject(kExamples + "paper-16-story.json");
        int all = 0, few = 0;
        const QString full = reportText(p, defaultSections(), &all);
        const QString refs = reportText(p, {"references"}, &few);
        QVERIFY(full.contains("Code inputs") && full.contains("Appendix: numerics"));
        QVERIFY(refs.contains("References") && refs.contains("Acceptance criterion"));
        QVERIFY(!refs.contains("Code inputs"));
        QVERIFY(!refs.contains("Assumptions and limitations"));
        QVERIFY(!refs.contains("The slab and the walls are rigid"));
        QVERIFY(!refs.contains("Appendix: numerics"));
        QVERIFY2(few < all, qPrintable(QString("%1 pages against %2").arg(few).arg(all)));
    }

    void sectionListIsChecked() {
        QCOMPARE(parseSections("inputs, references"), (SectionSet{"inputs", "references"}));
        QCOMPARE(parseSections("all"), allSections());
        try {
            parseSections("inputs,verdict");
            QFAIL("an unknown section was accepted");
        } catch (const ReportError& e) {
            const QString m = QString::fromUtf8(e.what());
            QVERIFY2(m.contains("'verdict' is not a report section"), e.what());
            QVERIFY2(m.contains("assumptions, symbols, inputs"), e.what());
        }
        QVERIFY_THROWS_EXCEPTION(ReportError, parseSections(" , "));
    }

    // The record's source, station, component and licence in the references.
    void recordSourcesAreCited() {
        const QString text =
            reportText(loadProject(kExamples + "paper-16-story-record.json"), {"references"});
        QVERIFY(
            text.contains("Pacoima Dam (upper left abutment), CDMG station 279, component 164°"));
        QVERIFY(text.contains("PEER NGA-West2 database, record sequence number (RSN) 77"));
        QVERIFY(text.contains("(BSD-2-Clause)"));
    }
};

QTEST_MAIN(TestReportContent)
#include "tst_report_content.moc"
