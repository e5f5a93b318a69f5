// SPDX-License-Identifier: GPL-3.0-or-later
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

} // namespace

ReportDocument buildReportDocument(const ReportSource& s, const ReportAnalysis& a) {
    const Project& p = s.project;
    ReportDocument doc;
    doc.title = QStringLiteral("kinstab design report — ") + qs(p.name);
    doc.footnote = QStringLiteral("kinstab " KINSTAB_VERSION ", ") +
                   s.created.toUTC().toString(QStringLiteral("yyyy-MM-dd"));
    doc.addTitle(titleBlock(s, a));
    addSummary(doc, p, a);
    addInputSections(doc, p, a);
    addCodeSections(doc, p, a);
    addExcitationSection(doc, p, a);
    addRecordSection(doc, p, a);
    addFloorsSection(doc, p, a);
    addSurfaceSections(doc, p, a);
    if (!a.check.codes.empty()) {
        const bool secondary = recordGoverns(p, a);
        doc.addSection(secondary ? QStringLiteral("Design check with the enveloped sine")
                                 : QStringLiteral("Design check: which failure governs"));
        if (secondary)
            doc.addParagraph(QStringLiteral(
                "For comparison only: the verdict of this report rests on the project's record "
                "(Summary). Here the same rule is applied to A_crit of the enveloped sine."));
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
