// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Breaks a ReportDocument into pages and paints them. Layout is done once for a given paint
// device (fonts are measured on it), so the page count is known before the first page is
// painted: the footer says "page n of N". Tables break between rows and repeat their header;
// figures, the title block and a heading with the start of what follows it stay together.

#include "report/ReportDocument.h"

#include <QPageSize>
#include <QPaintDevice>

#include <optional>
#include <vector>

namespace kinstab::report {

enum class PaperSize { A4, Letter };
QPageSize pageSizeOf(PaperSize p);
std::optional<PaperSize> paperSizeFromName(const QString& name); // "a4" | "letter"

// The fonts and measures of the house style, scaled to a device resolution.
struct ReportStyle {
    double dpi = 300;
    QString family = QStringLiteral("DejaVu Sans");
    double px(double millimetres) const { return millimetres * dpi / 25.4; }
    double pt(double points) const { return points * dpi / 72.0; }
    QFont font(double pointSize, bool bold = false, bool italic = false) const;
};

class PageLayout {
public:
    // pageRect: the whole page in device units; margins in millimetres.
    PageLayout(const ReportDocument& doc, QPaintDevice* device, const QRectF& pageRect,
               const ReportStyle& style, double marginMm = 20.0);

    int pageCount() const { return static_cast<int>(pages_.size()); }
    // The page (0-based) on which block `index` starts; -1 when it is not laid out.
    int pageOf(std::size_t index) const;
    void paintPage(QPainter& p, int page) const;

private:
    struct Piece {
        int block = 0;
        double y = 0;      // top, device units
        double height = 0; // on this page
        int rowFirst = 0;  // tables: rows [rowFirst, rowLast)
        int rowLast = 0;
    };
    using Page = std::vector<Piece>;

    void layout();
    double blockHeight(const Block& b) const;
    double minStartHeight(std::size_t index) const; // what must fit for the block to start here
    double keepWithHeading(std::size_t index) const;
    void placeTable(int index, double& y, Page& page);
    std::vector<double> columnWidths(const Table& t) const;
    double rowHeight(const Table& t, const QStringList& cells, bool bold) const;
    double textHeight(const QString& text, const QFont& f, double width) const;
    double figureWidth(const Figure& f) const;
    double captionHeight(const Figure& f) const;

    void paintPiece(QPainter& p, const Piece& piece) const;
    void paintTable(QPainter& p, const Table& t, const Piece& piece) const;
    double paintRow(QPainter& p, const Table& t, const QStringList& cells, double y, bool header,
                    bool bold) const;
    void paintTitle(QPainter& p, const TitleBlock& t, double y) const;
    QFont fittedFont(const QString& value, double room) const; // a title-block value's
    void paintFigure(QPainter& p, const Figure& f, double y) const;
    void paintFrame(QPainter& p, int page) const;

    const ReportDocument& doc_;
    QPaintDevice* device_;
    QRectF page_;
    QRectF body_;
    ReportStyle style_;
    std::vector<Page> pages_;
};

} // namespace kinstab::report
