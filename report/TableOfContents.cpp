// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/TableOfContents.h"

namespace kinstab::report {

namespace {

// The contents blocks for `doc`: a new page, the heading and one row per numbered section.
// pages[k]: the page of the k-th section ("" while not yet known).
std::vector<Block> contentsBlocks(const ReportDocument& doc, const QStringList& pages) {
    Table t{{"section", "page"}, {}, {8, 1}, {Align::Left, Align::Right}, {}};
    int k = 0;
    for (const Block& b : doc.blocks())
        if (b.kind == Block::Kind::Heading && b.heading.level == 1 &&
            b.heading.text.front().isDigit()) {
            t.rows.push_back({b.heading.text, k < pages.size() ? pages[k] : QStringLiteral("00")});
            ++k;
        }
    std::vector<Block> out(3);
    out[0].kind = Block::Kind::PageBreak;
    out[1].kind = Block::Kind::Heading;
    out[1].heading = {QStringLiteral("Contents"), 1};
    out[2].kind = Block::Kind::Table;
    out[2].table = t;
    return out;
}

// The page (1-based, as printed) of every numbered section of a laid-out document.
QStringList sectionPages(const ReportDocument& doc, const PageLayout& layout) {
    QStringList pages;
    const auto& blocks = doc.blocks();
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const Block& b = blocks[i];
        if (b.kind == Block::Kind::Heading && b.heading.level == 1 &&
            b.heading.text.front().isDigit())
            pages << QString::number(layout.pageOf(i) + 1);
    }
    return pages;
}

} // namespace

ReportDocument
withContents(const ReportDocument& doc,
             const std::function<std::unique_ptr<PageLayout>(const ReportDocument&)>& layoutOf) {
    const std::optional<std::size_t> at = doc.contentsAt();
    if (!at || layoutOf(doc)->pageCount() <= kContentsAfterPages) return doc;
    // Placeholder page numbers first: the draft shows where each section lands once the
    // contents page is in; the numbers themselves do not move anything.
    const ReportDocument draft = doc.withInserted(*at, contentsBlocks(doc, {}));
    const QStringList pages = sectionPages(draft, *layoutOf(draft));
    return doc.withInserted(*at, contentsBlocks(doc, pages));
}

} // namespace kinstab::report
