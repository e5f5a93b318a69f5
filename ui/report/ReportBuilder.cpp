// Assembles the report: title block, summary, then the sections whose analyses ran.
#include "ui/report/ReportSections.h"
#include "ui/report/ReportWriter.h"

#include <QCryptographicHash>
#include <QFileInfo>

namespace kinstab::ui::report {

namespace {

TitleBlock titleBlock(const ReportSource& s, const ReportAnalysis& a) {
    TitleBlock t;
    t.title = QStringLiteral("Kinetic stability design report");
    t.subtitle = qs(s.project.name);
    const QString file = s.fileName.isEmpty() ? QStringLiteral("(unsaved project)")
                                              : QFileInfo(s.fileName).fileName();
    t.fields.push_back({QStringLiteral("Project file"), file});
    if (!s.fileContents.isEmpty())
        t.fields.push_back(
            {QStringLiteral("SHA-256"),
             QString::fromLatin1(
                 QCryptographicHash::hash(s.fileContents, QCryptographicHash::Sha256).toHex())});
    t.fields.push_back({QStringLiteral("Date"),
                        s.created.toUTC().toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'"))});
    t.fields.push_back({QStringLiteral("Application"), QStringLiteral("kinstab " KINSTAB_VERSION)});
    t.fields.push_back({QStringLiteral("Model"), modelName(s.project)});
    QStringList codes;
    for (const CodeResult& r : a.codes)
        codes << shortCodeName(r.code);
    if (!codes.isEmpty()) t.fields.push_back({QStringLiteral("Codes"), codes.join("; ")});
    return t;
}

QString summaryText(const ReportAnalysis& a) {
    if (a.check.codes.empty())
        return QStringLiteral("No building code was selected, so no design check was made.");
    int kinetic = 0;
    for (const CodeVerdict& v : a.check.codes)
        kinetic += v.verdict == Verdict::KineticInstabilityGoverns;
    const QString outcome =
        kinetic == 0
            ? QStringLiteral(
                  "For every code selected, the required top-floor ratio lies below the "
                  "critical amplitude A_crit: member overstress governs, the slab does not "
                  "slide off before the structure reaches its code strength.")
            : QStringLiteral(
                  "For %1 of %2 codes the required top-floor ratio reaches A_crit: kinetic "
                  "instability governs there, and the slab seating must be checked.")
                  .arg(kinetic)
                  .arg(a.check.codes.size());
    return QStringLiteral("The check compares, for each code, the top-floor force ratio "
                          "F_top/w_top with A_crit(f), the smallest peak floor acceleration "
                          "(in g) that slides the slab off its walls at the building frequency "
                          "f = 1/T. ") +
           outcome;
}

} // namespace

ReportDocument buildReportDocument(const ReportSource& s, const ReportAnalysis& a) {
    const Project& p = s.project;
    ReportDocument doc;
    doc.title = QStringLiteral("kinstab design report — ") + qs(p.name);
    doc.footnote = QStringLiteral("kinstab " KINSTAB_VERSION ", ") +
                   s.created.toUTC().toString(QStringLiteral("yyyy-MM-dd"));
    doc.addTitle(titleBlock(s, a));
    if (!a.check.codes.empty()) {
        doc.addHeading(QStringLiteral("Summary"));
        doc.addParagraph(summaryText(a));
        addVerdictTable(doc, a);
        if (const QString r = recordSummary(a); !r.isEmpty()) doc.addParagraph(r);
    }
    addInputSections(doc, p);
    addCodeSections(doc, p, a);
    addExcitationSection(doc, p, a);
    addRecordSection(doc, p, a);
    addFloorsSection(doc, p, a);
    addSurfaceSections(doc, p, a);
    if (!a.check.codes.empty()) {
        doc.addSection(QStringLiteral("Design check: which failure governs"));
        doc.addParagraph(QStringLiteral(
            "Chapter V of the source report: below A_crit the structure reaches its code "
            "strength first (member overstress governs); at or above it the slab slides off "
            "(kinetic instability governs). Margin = A_crit / (F_top/w_top)."));
        addVerdictTable(doc, a);
        for (const CodeVerdict& v : a.check.codes)
            doc.addParagraph(qs(v.title) + ": " + qs(v.explanation) + ".", true);
    }
    addNumericsSection(doc, p, a);
    addReferences(doc, p);
    return doc;
}

} // namespace kinstab::ui::report
