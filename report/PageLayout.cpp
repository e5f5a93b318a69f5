// SPDX-License-Identifier: GPL-3.0-or-later
// PageLayout (report/PageLayout.h): the blocks measured on the device and placed on pages; the
// painting in PagePainting.cpp.
#include "report/PageLayout.h"

#include "report/TypeSizes.h"
#include "report/WrappedText.h"

#include <QFontMetricsF>

#include <algorithm>
#include <numeric>

namespace kinstab::report {

QPageSize pageSizeOf(PaperSize p) {
    return QPageSize(p == PaperSize::A4 ? QPageSize::A4 : QPageSize::Letter);
}

std::optional<PaperSize> paperSizeFromName(const QString& name) {
    if (name == QLatin1String("a4")) return PaperSize::A4;
    if (name == QLatin1String("letter")) return PaperSize::Letter;
    return std::nullopt;
}

QFont ReportStyle::font(double pointSize, bool bold, bool italic) const {
    QFont f(family);
    // Sized in device pixels so that measuring and painting agree on any device.
    f.setPixelSize(std::max(1, static_cast<int>(std::lround(pt(pointSize)))));
    f.setBold(bold);
    f.setItalic(italic);
    f.setHintingPreference(QFont::PreferNoHinting);
    return f;
}

PageLayout::PageLayout(const ReportDocument& doc, QPaintDevice* device, const QRectF& pageRect,
                       const ReportStyle& style, double marginMm)
    : doc_(doc), device_(device), page_(pageRect), style_(style) {
    const double m = style_.px(marginMm);
    body_ = page_.adjusted(m, m, -m, -m);
    layout();
}

double PageLayout::textHeight(const QString& text, const QFont& f, double width) const {
    return wrappedHeight(text, f, width, device_);
}

std::vector<double> PageLayout::columnWidths(const Table& t) const {
    const std::size_t n = static_cast<std::size_t>(t.header.size());
    std::vector<double> w = t.columnWeights;
    if (w.size() != n) w.assign(n, 1.0);
    const double sum = std::accumulate(w.begin(), w.end(), 0.0);
    for (double& x : w)
        x *= body_.width() / sum;
    return w;
}

double PageLayout::rowHeight(const Table& t, const QStringList& cells, bool bold) const {
    const std::vector<double> w = columnWidths(t);
    const QFont f = style_.font(kTablePt, bold);
    const double pad = style_.px(1.2);
    double h = 0;
    for (int c = 0; c < cells.size() && c < static_cast<int>(w.size()); ++c)
        h = std::max(h, textHeight(cells[c], f, w[c] - 2 * pad));
    return h + 2 * pad;
}

double PageLayout::figureWidth(const Figure& f) const {
    // Shrink a figure that would be taller than two thirds of the body.
    const double maxH = body_.height() * 0.66;
    return std::min(body_.width(), maxH / f.aspect);
}

double PageLayout::captionHeight(const Figure& f) const {
    if (f.caption.isEmpty()) return 0;
    return style_.px(2) +
           textHeight(f.caption, style_.font(kCaptionPt, false, true), body_.width());
}

double PageLayout::blockHeight(const Block& b) const {
    const double gap = style_.px(2.5);
    switch (b.kind) {
    case Block::Kind::Heading:
        return style_.px(b.heading.level <= 1 ? 5 : 3) +
               textHeight(b.heading.text, style_.font(headingPt(b.heading.level), true),
                          body_.width()) +
               style_.px(1.5);
    case Block::Kind::Paragraph:
        return textHeight(b.paragraph.text, style_.font(b.paragraph.small ? kSmallPt : kBodyPt),
                          body_.width()) +
               gap;
    case Block::Kind::Figure:
        return figureWidth(b.figure) * b.figure.aspect + captionHeight(b.figure) + 2 * gap;
    case Block::Kind::Title: {
        // The widths paintTitle paints in: the body less an inset of 4 mm each side.
        const double inside = body_.width() - style_.px(8);
        double h = style_.px(6) + textHeight(b.title.title, style_.font(kTitlePt, true), inside);
        if (!b.title.subtitle.isEmpty())
            h += textHeight(b.title.subtitle, style_.font(kBodyPt + 1), inside) + style_.px(2);
        const QFontMetricsF fm(style_.font(kBodyPt), device_);
        h += b.title.fields.size() * fm.lineSpacing() + style_.px(8);
        return h;
    }
    case Block::Kind::Table:
    case Block::Kind::PageBreak:
        return 0;
    }
    return 0;
}

double PageLayout::minStartHeight(std::size_t index) const {
    if (index >= doc_.blocks().size()) return 0;
    const Block& b = doc_.blocks()[index];
    if (b.kind != Block::Kind::Table) return blockHeight(b);
    // A table may start when its header and two rows fit (no orphaned header).
    double h = rowHeight(b.table, b.table.header, true);
    for (std::size_t r = 0; r < b.table.rows.size() && r < 2; ++r)
        h += rowHeight(b.table, b.table.rows[r], false);
    return h;
}

// What must stay on the page with a heading: the headings right under it, then the start of the
// content; an introducing paragraph takes its figure along (no heading alone at a page foot, no
// heading and caption text with the figure on the next page).
double PageLayout::keepWithHeading(std::size_t index) const {
    const auto& blocks = doc_.blocks();
    double h = 0;
    while (index < blocks.size() && blocks[index].kind == Block::Kind::Heading)
        h += blockHeight(blocks[index++]);
    h += minStartHeight(index);
    if (index + 1 < blocks.size() && blocks[index].kind == Block::Kind::Paragraph &&
        blocks[index + 1].kind == Block::Kind::Figure)
        h += blockHeight(blocks[index + 1]);
    return h;
}

void PageLayout::placeTable(int index, double& y, Page& page) {
    const Table& t = doc_.blocks()[index].table;
    const double header = rowHeight(t, t.header, true);
    int row = 0;
    const int n = static_cast<int>(t.rows.size());
    do {
        Piece piece{index, y, header, row, row};
        while (row < n) {
            const bool bold = std::count(t.boldRows.begin(), t.boldRows.end(), row) > 0;
            const double h = rowHeight(t, t.rows[row], bold);
            const bool firstRow = piece.rowLast == piece.rowFirst;
            if (y + piece.height + h > body_.bottom() && !firstRow) break;
            piece.height += h;
            ++row;
            piece.rowLast = row;
        }
        page.push_back(piece);
        y += piece.height + style_.px(3);
        if (row < n) {
            pages_.push_back(std::move(page));
            page.clear();
            y = body_.top();
        }
    } while (row < n);
}

void PageLayout::layout() {
    pages_.clear();
    Page page;
    double y = body_.top();
    const auto& blocks = doc_.blocks();
    auto newPage = [&] {
        pages_.push_back(std::move(page));
        page.clear();
        y = body_.top();
    };
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const Block& b = blocks[i];
        if (b.kind == Block::Kind::PageBreak) {
            if (!page.empty()) newPage();
            continue;
        }
        double need = minStartHeight(i);
        if (b.kind == Block::Kind::Heading) need += keepWithHeading(i + 1);
        if (y + need > body_.bottom() && !page.empty()) newPage();
        if (b.kind == Block::Kind::Table) {
            placeTable(static_cast<int>(i), y, page);
            continue;
        }
        const double h = blockHeight(b);
        page.push_back(Piece{static_cast<int>(i), y, h, 0, 0});
        y += h;
    }
    if (!page.empty() || pages_.empty()) pages_.push_back(std::move(page));
}

int PageLayout::pageOf(std::size_t index) const {
    for (std::size_t page = 0; page < pages_.size(); ++page)
        for (const Piece& piece : pages_[page])
            if (piece.block == static_cast<int>(index)) return static_cast<int>(page);
    return -1;
}

} // namespace kinstab::report
