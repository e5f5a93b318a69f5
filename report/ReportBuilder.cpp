// SPDX-License-Identifier: GPL-3.0-or-later
// Assembles the report: title block, summary, then the sections whose analyses ran.
#include "report/CodeStyle.h"
#include "report/ReportSections.h"
#include "report/ReportWriter.h"
#include "report/SectionCatalog.h"

#include <QCryptographicHash>
#include <QFileInfo>

namespace kinstab::report {

namespace {

// One title-block line when the project says it; nothing for an empty field.
void addField(TitleBlock& t, const QString& key, const std::string& value) {
    if (!value.empty()) t.fields.push_back({key, qs(value)});
}

void addInfoFields(TitleBlock& t, const ProjectInfo& in) {
    addField(t, QStringLiteral("Project no."), in.projectNumber);
    addField(t, QStringLiteral("Client"), in.client);
    addField(t, QStringLiteral("Site"), in.siteAddress);
    std::string engineer = in.engineer;
    if (!in.registration.empty())
        engineer += (engineer.empty() ? "" : ", ") + std::string("reg. no. ") + in.registration;
    addField(t, QStringLiteral("Engineer"), engineer);
    addField(t, QStringLiteral("Firm"), in.firm);
    if (!in.preparedBy.empty() || !in.checkedBy.empty())
        addField(t, QStringLiteral("Prepared by"),
                 (in.preparedBy.empty() ? "—" : in.preparedBy) + ", checked by " +
                     (in.checkedBy.empty() ? "—" : in.checkedBy));
    if (!in.revisions.empty()) {
        const Revision& r = in.revisions.back();
        addField(t, QStringLiteral("Revision"), r.id + ", " + r.date);
    }
}

TitleBlock titleBlock(const ReportSource& s, const ReportAnalysis& a) {
    TitleBlock t;
    t.title = QStringLiteral("Kinetic stability design report");
    t.subtitle = qs(s.project.name);
    addInfoFields(t, s.project.info);
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
    // The application and version stand in the footer of every page and in the disclaimer.
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
    addRevisions(doc, p);
    addSignatureBlock(doc, p); // with the title block, so that the signed page is page 1
    addSummary(doc, p, a);
    addAcceptanceCriterion(doc, p, a);
    doc.markContents();
    for (const SectionEntry& e : sectionCatalog())
        if (s.sections.count(e.key)) e.add(doc, p, a);
    addRevisionHistory(doc, p); // what page 1 leaves out of the revision table
    return doc;
}

} // namespace kinstab::report
