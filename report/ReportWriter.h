// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The design report (docs/user-guide.md, issue #5): one function builds the document from a project
// and the analyses already computed, one writes it as a vector PDF. The GUI's File → Export report…
// and `kinstab-cli report` both call writeReport, so they produce the same document.

#include "core/io/Project.h"
#include "report/PageLayout.h"
#include "report/ReportAnalysis.h"
#include "report/ReportDocument.h"
#include "report/ReportError.h"
#include "report/SectionCatalog.h"

#include <QByteArray>
#include <QDateTime>
#include <QString>

namespace kinstab::report {

struct ReportSource {
    Project project;
    QString fileName;        // the project file as the user named it ("" when unsaved)
    QByteArray fileContents; // its bytes, for the SHA-256 in the title block
    QDateTime created = QDateTime::currentDateTimeUtc();
    SectionSet sections = defaultSections(); // the optional sections to print (SectionCatalog.h)
};

ReportDocument buildReportDocument(const ReportSource& source, const ReportAnalysis& analysis);

// Renders the PDF (vector text and line art) into bytes; returns the number of pages.
int renderReportPdf(const ReportDocument& doc, PaperSize paper, QByteArray& bytes);

// Renders and writes the PDF through core's atomic writer. Returns the number of pages; throws
// ReportError for a missing folder, kinstab::WriteError when the file cannot be written (the
// old file, if any, is then left as it was).
int writeReportPdf(const ReportDocument& doc, const QString& path, PaperSize paper);

// Both in one: what the GUI and the CLI call.
int writeReport(const ReportSource& source, const ReportAnalysis& analysis, const QString& path,
                PaperSize paper);

} // namespace kinstab::report
