// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A report as a flow of blocks — headings, paragraphs, tables, figures — independent of the
// page size. PageLayout breaks it into pages: tables break between rows (the header repeats),
// figures and the title block never split.

#include <QColor>
#include <QPainter>
#include <QRectF>
#include <QString>
#include <QStringList>

#include <functional>
#include <optional>
#include <vector>

namespace kinstab::report {

struct Heading {
    QString text;
    int level = 1; // 1: section, 2: subsection
};

struct Paragraph {
    QString text;
    bool small = false; // notes and references
};

enum class Align { Left, Right };

struct Table {
    QStringList header;
    std::vector<QStringList> rows;
    std::vector<double> columnWeights; // relative widths; empty: equal
    std::vector<Align> align;          // per column; empty: left
    std::vector<int> boldRows;         // rows set in bold (totals, results)
};

// A figure paints itself into the rectangle it is given (device units of the painter).
using FigurePainter = std::function<void(QPainter&, const QRectF&)>;

struct Figure {
    FigurePainter paint;
    double aspect = 0.62; // height / width of the drawing area
    QString caption;
};

// The boxed block at the top of page 1: title, then key: value lines.
struct TitleBlock {
    QString title;
    QString subtitle;
    std::vector<std::pair<QString, QString>> fields;
};

struct PageBreak {};

struct Block {
    enum class Kind { Heading, Paragraph, Table, Figure, Title, PageBreak } kind;
    Heading heading;
    Paragraph paragraph;
    Table table;
    Figure figure;
    TitleBlock title;
};

class ReportDocument {
public:
    QString title;    // PDF metadata and running header
    QString footnote; // left of the page number in the footer

    void addTitle(TitleBlock t);
    void addHeading(const QString& text, int level = 1);
    void addSection(const QString& text); // a numbered level-1 heading
    void addParagraph(const QString& text, bool small = false);
    void addTable(Table t);
    void addFigure(Figure f);  // numbers the caption: "Figure n. ..."
    void addDrawing(Figure f); // a form or block drawn in place (the signature block): unnumbered
    void addPageBreak();
    // Where a table of contents goes if the report turns out long (report/TableOfContents.h).
    void markContents() { contentsAt_ = blocks_.size(); }
    std::optional<std::size_t> contentsAt() const { return contentsAt_; }
    // A copy with `extra` inserted before block `at`.
    ReportDocument withInserted(std::size_t at, std::vector<Block> extra) const;

    const std::vector<Block>& blocks() const { return blocks_; }

private:
    std::vector<Block> blocks_;
    std::optional<std::size_t> contentsAt_;
    int sections_ = 0;
    int figures_ = 0;
};

} // namespace kinstab::report
