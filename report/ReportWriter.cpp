// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/ReportWriter.h"

#include "core/io/AtomicFile.h"
#include "report/TableOfContents.h"

#include <QBuffer>
#include <QDir>
#include <QFileInfo>
#include <QPainter>
#include <QPdfWriter>

namespace kinstab::report {

int renderReportPdf(const ReportDocument& doc, PaperSize paper, QByteArray& bytes) {
    QBuffer buffer(&bytes); // in memory, so that the file is written whole or not at all
    buffer.open(QIODevice::WriteOnly);
    QPdfWriter pdf(&buffer);
    pdf.setPageSize(pageSizeOf(paper));
    pdf.setPageMargins(QMarginsF(0, 0, 0, 0));
    pdf.setResolution(300);
    pdf.setTitle(doc.title);
    pdf.setCreator(QStringLiteral("kinstab " KINSTAB_VERSION));
    QPainter painter;
    if (!painter.begin(&pdf)) throw ReportError("cannot start a PDF");
    ReportStyle style;
    style.dpi = pdf.resolution();
    const QRectF page(0, 0, pdf.width(), pdf.height());
    const auto layoutOf = [&](const ReportDocument& d) {
        return std::make_unique<PageLayout>(d, &pdf, page, style);
    };
    const ReportDocument printed = withContents(doc, layoutOf);
    const PageLayout layout(printed, &pdf, page, style);
    for (int k = 0; k < layout.pageCount(); ++k) {
        if (k > 0) pdf.newPage();
        layout.paintPage(painter, k);
    }
    painter.end();
    return layout.pageCount();
}

int writeReportPdf(const ReportDocument& doc, const QString& path, PaperSize paper) {
    const QFileInfo info(path);
    if (!info.absoluteDir().exists())
        throw ReportError("the folder " + info.absolutePath().toStdString() + " does not exist");
    QByteArray bytes;
    const int pages = renderReportPdf(doc, paper, bytes);
    writeFileAtomically(path.toStdString(), std::string_view(bytes.constData(), bytes.size()));
    return pages;
}

int writeReport(const ReportSource& source, const ReportAnalysis& analysis, const QString& path,
                PaperSize paper) {
    return writeReportPdf(buildReportDocument(source, analysis), path, paper);
}

} // namespace kinstab::report
