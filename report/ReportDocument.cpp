// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/ReportDocument.h"

#include <algorithm>
#include <iterator>
#include <utility>

namespace kinstab::report {

void ReportDocument::addTitle(TitleBlock t) {
    Block b{Block::Kind::Title, {}, {}, {}, {}, std::move(t)};
    blocks_.push_back(std::move(b));
}

void ReportDocument::addHeading(const QString& text, int level) {
    Block b{Block::Kind::Heading, Heading{text, level}, {}, {}, {}, {}};
    blocks_.push_back(std::move(b));
}

void ReportDocument::addSection(const QString& text) {
    addHeading(QString::number(++sections_) + QStringLiteral("  ") + text, 1);
}

void ReportDocument::addParagraph(const QString& text, bool small) {
    Block b{Block::Kind::Paragraph, {}, Paragraph{text, small}, {}, {}, {}};
    blocks_.push_back(std::move(b));
}

void ReportDocument::addTable(Table t) {
    Block b{Block::Kind::Table, {}, {}, std::move(t), {}, {}};
    blocks_.push_back(std::move(b));
}

void ReportDocument::addFigure(Figure f) {
    f.caption = QStringLiteral("Figure %1. ").arg(++figures_) + f.caption;
    Block b{Block::Kind::Figure, {}, {}, {}, std::move(f), {}};
    blocks_.push_back(std::move(b));
}

void ReportDocument::addDrawing(Figure f) {
    Block b{Block::Kind::Figure, {}, {}, {}, std::move(f), {}};
    blocks_.push_back(std::move(b));
}

ReportDocument ReportDocument::withInserted(std::size_t at, std::vector<Block> extra) const {
    ReportDocument d = *this;
    at = std::min(at, d.blocks_.size());
    d.blocks_.insert(d.blocks_.begin() + static_cast<std::ptrdiff_t>(at),
                     std::make_move_iterator(extra.begin()), std::make_move_iterator(extra.end()));
    d.contentsAt_.reset();
    return d;
}

void ReportDocument::addPageBreak() {
    blocks_.push_back(Block{Block::Kind::PageBreak, {}, {}, {}, {}, {}});
}

} // namespace kinstab::report
