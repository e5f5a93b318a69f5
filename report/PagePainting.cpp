// SPDX-License-Identifier: GPL-3.0-or-later
// PageLayout, continued: the pages painted - the frame with its page number, each piece of a
// block (heading, paragraph, table rows, title block, figure) where layout() placed it.

#include "report/PageLayout.h"
#include "report/TypeSizes.h"
#include "report/WrappedText.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>

namespace kinstab::report {

void PageLayout::paintPage(QPainter& p, int page) const {
    if (page < 0 || page >= pageCount()) return;
    paintFrame(p, page);
    for (const Piece& piece : pages_[page])
        paintPiece(p, piece);
}

void PageLayout::paintFrame(QPainter& p, int page) const {
    p.save();
    p.setPen(QPen(QColor(90, 90, 90), style_.pt(0.5)));
    const double top = body_.top() - style_.px(7);
    const double bottom = body_.bottom() + style_.px(6);
    p.setFont(style_.font(kSmallPt));
    const QFontMetricsF fm(p.font(), device_);
    // The title holds the project's name (up to 200 characters): cut to the line it has.
    p.drawText(QPointF(body_.left(), top),
               fm.elidedText(doc_.title, Qt::ElideRight, body_.width()));
    p.drawLine(QPointF(body_.left(), top + style_.px(1.5)),
               QPointF(body_.right(), top + style_.px(1.5)));
    p.drawLine(QPointF(body_.left(), bottom - fm.ascent() - style_.px(1.5)),
               QPointF(body_.right(), bottom - fm.ascent() - style_.px(1.5)));
    p.drawText(QPointF(body_.left(), bottom), doc_.footnote);
    const QString number = QStringLiteral("page %1 of %2").arg(page + 1).arg(pageCount());
    p.drawText(QPointF(body_.right() - fm.horizontalAdvance(number), bottom), number);
    p.restore();
}

void PageLayout::paintPiece(QPainter& p, const Piece& piece) const {
    const Block& b = doc_.blocks()[piece.block];
    p.save();
    p.setPen(Qt::black);
    switch (b.kind) {
    case Block::Kind::Heading: {
        const double top = piece.y + style_.px(b.heading.level <= 1 ? 5 : 3);
        p.setFont(style_.font(headingPt(b.heading.level), true));
        paintWrapped(p, QRectF(body_.left(), top, body_.width(), piece.height), b.heading.text);
        break;
    }
    case Block::Kind::Paragraph:
        p.setFont(style_.font(b.paragraph.small ? kSmallPt : kBodyPt));
        paintWrapped(p, QRectF(body_.left(), piece.y, body_.width(), piece.height),
                     b.paragraph.text);
        break;
    case Block::Kind::Table:
        paintTable(p, b.table, piece);
        break;
    case Block::Kind::Figure:
        paintFigure(p, b.figure, piece.y);
        break;
    case Block::Kind::Title:
        paintTitle(p, b.title, piece.y);
        break;
    case Block::Kind::PageBreak:
        break;
    }
    p.restore();
}

double PageLayout::paintRow(QPainter& p, const Table& t, const QStringList& cells, double y,
                            bool header, bool bold) const {
    const std::vector<double> w = columnWidths(t);
    const double h = rowHeight(t, cells, header || bold);
    const double pad = style_.px(1.2);
    if (header) p.fillRect(QRectF(body_.left(), y, body_.width(), h), QColor(232, 236, 242));
    p.setFont(style_.font(kTablePt, header || bold));
    double x = body_.left();
    for (int c = 0; c < cells.size() && c < static_cast<int>(w.size()); ++c) {
        const bool right = c < static_cast<int>(t.align.size()) && t.align[c] == Align::Right;
        paintWrapped(p, QRectF(x + pad, y + pad, w[c] - 2 * pad, h - 2 * pad), cells[c],
                     right ? Qt::AlignRight : Qt::AlignLeft);
        x += w[c];
    }
    p.setPen(QPen(QColor(150, 150, 150), style_.pt(header ? 0.8 : 0.3)));
    p.drawLine(QPointF(body_.left(), y + h), QPointF(body_.right(), y + h));
    p.setPen(Qt::black);
    return h;
}

void PageLayout::paintTable(QPainter& p, const Table& t, const Piece& piece) const {
    double y = piece.y;
    p.setPen(QPen(Qt::black, style_.pt(0.8)));
    p.drawLine(QPointF(body_.left(), y), QPointF(body_.right(), y));
    p.setPen(Qt::black);
    y += paintRow(p, t, t.header, y, true, true);
    for (int r = piece.rowFirst; r < piece.rowLast; ++r) {
        const bool bold = std::count(t.boldRows.begin(), t.boldRows.end(), r) > 0;
        y += paintRow(p, t, t.rows[r], y, false, bold);
    }
}

// One line per title-block field: a value a little too wide for it (a SHA-256 of wide hex
// digits) is set smaller, down to 80 %, to stand whole; a longer one (a 200-character client) is
// then cut with "…", as the block has one line for it.
QFont PageLayout::fittedFont(const QString& value, double room) const {
    QFont f = style_.font(kBodyPt);
    const double width = QFontMetricsF(f, device_).horizontalAdvance(value);
    if (width > room)
        f.setPixelSize(std::max(1, static_cast<int>(f.pixelSize() * std::max(0.8, room / width))));
    return f;
}

void PageLayout::paintTitle(QPainter& p, const TitleBlock& t, double y) const {
    const double inset = style_.px(4);
    const double width = body_.width() - 2 * inset;
    double cy = y + inset;
    p.setFont(style_.font(kTitlePt, true));
    const double th = textHeight(t.title, p.font(), width);
    paintWrapped(p, QRectF(body_.left() + inset, cy, width, th), t.title);
    cy += th + style_.px(1);
    if (!t.subtitle.isEmpty()) {
        p.setFont(style_.font(kBodyPt + 1));
        const double sh = textHeight(t.subtitle, p.font(), width);
        paintWrapped(p, QRectF(body_.left() + inset, cy, width, sh), t.subtitle);
        cy += sh + style_.px(2);
    }
    const QFont bold = style_.font(kBodyPt, true);
    const QFont plain = style_.font(kBodyPt);
    const QFontMetricsF fm(plain, device_);
    double keyWidth = 0;
    for (const auto& [k, v] : t.fields)
        keyWidth = std::max(keyWidth, QFontMetricsF(bold, device_).horizontalAdvance(k));
    for (const auto& [k, v] : t.fields) {
        cy += fm.lineSpacing();
        p.setFont(bold);
        p.drawText(QPointF(body_.left() + inset, cy), k);
        const double room = width - keyWidth - style_.px(4);
        p.setFont(fittedFont(v, room));
        p.drawText(QPointF(body_.left() + inset + keyWidth + style_.px(4), cy),
                   QFontMetricsF(p.font(), device_).elidedText(v, Qt::ElideRight, room));
    }
    const double bottom =
        y + blockHeight(Block{Block::Kind::Title, {}, {}, {}, {}, t}) - style_.px(3);
    p.setPen(QPen(Qt::black, style_.pt(1.2)));
    p.setBrush(Qt::NoBrush);
    p.drawRect(QRectF(body_.left(), y, body_.width(), bottom - y));
}

void PageLayout::paintFigure(QPainter& p, const Figure& f, double y) const {
    const double w = figureWidth(f);
    const double gap = style_.px(2.5);
    const QRectF area(body_.left() + (body_.width() - w) / 2, y + gap, w, w * f.aspect);
    p.save();
    p.setClipRect(area.adjusted(-2, -2, 2, 2));
    f.paint(p, area);
    p.restore();
    if (f.caption.isEmpty()) return;
    p.setFont(style_.font(kCaptionPt, false, true));
    const double top = area.bottom() + style_.px(2);
    paintWrapped(p, QRectF(body_.left(), top, body_.width(), captionHeight(f)), f.caption);
}

} // namespace kinstab::report
