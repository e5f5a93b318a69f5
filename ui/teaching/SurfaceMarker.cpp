// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/SurfaceMarker.h"
#include "ui/NiceTicks.h"

#include "ui/teaching/TextScale.h"

#include "ui/teaching/StateStyle.h"
#include "ui/teaching/TracePainter.h"

#include <QFontMetricsF>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {

std::vector<double> spread(double lo, double hi, int n) {
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        v[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
    return v;
}

MarkerMap computeMap(const TeachingParams& p, const MapRange& r, MapMode mode,
                     SweepControl* control) {
    MarkerMap m;
    m.context = p;
    m.range = r;
    m.mode = mode;
    const bool planar = p.model == TeachingModel::Planar;
    const PlanarCase pc = p.toPlanarCase(); // a sweep keeps tau_c only (docs/theory.md §6.6)
    const Slab1DCase c = p.toCase();
    m.tauRef = c.tauRef();
    SweepGrid grid;
    if (mode == MapMode::Surface) {
        const int n = planar ? SurfaceMarker::kPlanarCells : SurfaceMarker::kCells;
        grid.amplitudes = spread(r.aMin, r.aMax, n);
        grid.frequencies = spread(r.fMin, r.fMax, n);
    } else {
        grid.amplitudes = spread(r.aMin, r.aMax, SurfaceMarker::kSlicePoints);
        grid.frequencies = {p.frequencyHz};
    }
    m.sweep = runSweep(grid, planar ? planarPoint(pc) : slab1DPoint(c), control,
                       1); // one thread: the GUI keeps a core
    m.gamma = collapseFactors(m.sweep, m.tauRef);
    return m;
}

// White (stable) through yellow and orange to dark red as gamma_c grows.
QColor gammaColor(double g, double gMax) {
    if (!(g > 0)) return QColor(0xee, 0xf2, 0xf6);
    const double x = std::clamp(g / std::max(gMax, 1e-12), 0.0, 1.0);
    return QColor::fromHsvF(0.16 * (1.0 - x), 0.35 + 0.6 * x, 1.0 - 0.45 * x);
}

} // namespace

SurfaceMarker::SurfaceMarker(QWidget* parent) : QWidget(parent), job_(this) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setToolTip(tr("Click to run that amplitude and frequency"));
}

SurfaceMarker::~SurfaceMarker() = default;

bool sameSweep(const SweepKey& a, const SweepKey& b) {
    return a.mode == b.mode && a.range == b.range && a.params.envelope == b.params.envelope &&
           a.params.scale == b.params.scale && a.params.mu == b.params.mu &&
           a.params.wallWidthM == b.params.wallWidthM && a.params.limit == b.params.limit &&
           a.params.model == b.params.model && a.params.fyHz == b.params.fyHz &&
           a.params.ayRatio == b.params.ayRatio && a.params.theta == b.params.theta &&
           (a.mode == MapMode::Surface || a.params.frequencyHz == b.params.frequencyHz);
}

void SurfaceMarker::setContext(const TeachingParams& p, const MapRange& range, MapMode mode) {
    current_ = {p, range, mode};
    const bool shown = hasMap_ && sameSweep(current_, {map_.context, map_.range, map_.mode});
    const bool coming = isComputing() && sameSweep(current_, running_);
    if (!shown && !coming) start();
    update();
}

// A sweep still running is superseded: the job cancels it and drops its result.
void SurfaceMarker::start() {
    running_ = current_;
    job_.start<MarkerMap>(
        [k = current_](JobContext& job) {
            return computeMap(k.params, k.range, k.mode, &job.control);
        },
        [this](const MarkerMap& m) { onFinished(m); });
}

void SurfaceMarker::onFinished(const MarkerMap& m) {
    if (m.sweep.cancelled) return; // only the destructor cancels the current job
    map_ = m;
    hasMap_ = true;
    if (!sameSweep(current_, running_)) start(); // the context moved on meanwhile
    update();
    emit mapReady();
}

namespace {

// One line of the map's label text, from the view's font (larger in presentation mode).
double labelLine(const QFont& viewFont) {
    return std::ceil(scaledPixels(viewFont, 11, kLabelMaxScale) * 1.45);
}

} // namespace

QRectF SurfaceMarker::plotRect() const {
    // Left: tick labels and the rotated axis title; top: the heading; bottom: ticks and titles.
    const double lh = labelLine(font());
    return QRectF(rect()).adjusted(3.6 * lh, 1.4 * lh, -10, -2 * lh - 2);
}

namespace {

// The plot area and its value ranges: x is f (surface) or A (slice), y is A or tau_c.
struct Plot {
    QRectF r;
    double xLo, xHi, yLo, yHi;
    double lh; // one line of label text
    double x(double v) const { return r.left() + r.width() * (v - xLo) / (xHi - xLo); }
    double y(double v) const { return r.bottom() - r.height() * (v - yLo) / (yHi - yLo); }
};

void paintSurfaceCells(QPainter& p, const Plot& pl, const MarkerMap& map) {
    p.save();
    p.setClipRect(pl.r);
    const auto& g = map.sweep.grid;
    const double gMax = *std::max_element(map.gamma.begin(), map.gamma.end());
    const double cw = pl.r.width() / static_cast<double>(g.frequencies.size() - 1);
    const double ch = pl.r.height() / static_cast<double>(g.amplitudes.size() - 1);
    for (std::size_t i = 0; i < g.amplitudes.size(); ++i)
        for (std::size_t j = 0; j < g.frequencies.size(); ++j) {
            const QPointF c(pl.x(g.frequencies[j]), pl.y(g.amplitudes[i]));
            p.fillRect(QRectF(c.x() - cw / 2, c.y() - ch / 2, cw + 0.5, ch + 0.5),
                       gammaColor(map.gamma[i * g.frequencies.size() + j], gMax));
        }
    p.restore();
    p.setPen(QColor(0x55, 0x55, 0x55));
    // Beside the axis title on the second line under the plot; shortened rather than overlap.
    const QString title = QStringLiteral("f [Hz]");
    const QFontMetricsF fm(p.font());
    const double room = pl.r.width() - fm.horizontalAdvance(title) - pl.lh;
    p.drawText(QRectF(pl.r.left(), pl.r.bottom() + pl.lh, pl.r.width(), pl.lh), Qt::AlignRight,
               fm.elidedText(QStringLiteral("pale: stable; darkest: γc = %1").arg(gMax, 0, 'f', 2),
                             Qt::ElideRight, room));
}

// Fig. 34: tau_c against A; a stable amplitude is a dot along the top.
void paintSlice(QPainter& p, const Plot& pl, const MarkerMap& map) {
    p.setPen(QPen(stateColor(DisplayState::Collapse), 1.5));
    QPointF last;
    bool have = false;
    for (std::size_t i = 0; i < map.sweep.points.size(); ++i) {
        const auto& pt = map.sweep.points[i];
        const double x = pl.x(map.sweep.grid.amplitudes[i]);
        if (pt.outcome != Outcome::Collapsed) {
            p.drawText(QRectF(x - 4, pl.r.top(), 8, pl.lh), Qt::AlignCenter, QStringLiteral("·"));
            have = false;
            continue;
        }
        const QPointF q(x, pl.y(pt.tauC));
        if (have) p.drawLine(last, q);
        p.drawEllipse(q, 2, 2);
        last = q;
        have = true;
    }
    p.setPen(QColor(0x55, 0x55, 0x55));
    p.drawText(QRectF(pl.r.left() + 4, pl.r.top() + pl.lh * 0.8, pl.r.width(), pl.lh),
               Qt::AlignLeft, QStringLiteral("τc (stable: dots on top)"));
}

void paintAxes(QPainter& p, const Plot& pl, bool surface) {
    p.setPen(QColor(0x44, 0x44, 0x44));
    p.setBrush(Qt::NoBrush);
    p.drawRect(pl.r);
    const double xs = niceTickStep(pl.xHi - pl.xLo, 4), ys = niceTickStep(pl.yHi - pl.yLo, 4);
    for (double v = std::ceil(pl.xLo / xs) * xs; v <= pl.xHi + 1e-9; v += xs)
        p.drawText(QRectF(pl.x(v) - 1.5 * pl.lh, pl.r.bottom() + 1, 3 * pl.lh, pl.lh),
                   Qt::AlignCenter, QString::number(v, 'g', 3));
    for (double v = std::ceil(pl.yLo / ys) * ys; v <= pl.yHi + 1e-9; v += ys)
        p.drawText(QRectF(0, pl.y(v) - pl.lh / 2, pl.r.left() - 4, pl.lh),
                   Qt::AlignRight | Qt::AlignVCenter, QString::number(v, 'g', 3));
    p.drawText(QRectF(pl.r.left(), pl.r.bottom() + pl.lh, pl.r.width(), pl.lh), Qt::AlignLeft,
               surface ? QStringLiteral("f [Hz]") : QStringLiteral("A [g]"));
    p.save();
    p.translate(pl.lh * 0.6, pl.r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-pl.r.height() / 2, -pl.lh / 2, pl.r.height(), pl.lh), Qt::AlignCenter,
               surface ? QStringLiteral("A [g]") : QStringLiteral("τc"));
    p.restore();
}

// Cross-hairs at (f, A) on the surface; a dashed line at A on the slice.
void paintMarker(QPainter& p, const Plot& pl, const TeachingParams& cur, bool surface) {
    const double cx = pl.x(surface ? cur.frequencyHz : cur.amplitude);
    const double cy = surface ? pl.y(cur.amplitude) : pl.r.center().y();
    const QPointF c(std::clamp(cx, pl.r.left(), pl.r.right()),
                    std::clamp(cy, pl.r.top(), pl.r.bottom()));
    if (!surface) {
        p.setPen(QPen(QColor(0x10, 0x10, 0x10), 1.5, Qt::DashLine));
        p.drawLine(QPointF(c.x(), pl.r.top()), QPointF(c.x(), pl.r.bottom()));
        return;
    }
    p.setPen(QPen(QColor(0x10, 0x10, 0x10), 2));
    p.drawEllipse(c, 6, 6);
    for (const QPointF d : {QPointF(1, 0), QPointF(-1, 0), QPointF(0, 1), QPointF(0, -1)})
        p.drawLine(c + 6 * d, c + 10 * d);
}

} // namespace

void SurfaceMarker::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), Qt::white);
    p.setRenderHint(QPainter::Antialiasing);
    QFont font = p.font();
    font.setPixelSize(scaledPixels(p, 11, kLabelMaxScale)); // larger in presentation mode
    p.setFont(font);
    const bool surface = current_.mode == MapMode::Surface;
    const QString ref = current_.params.scale == TauScale::TauRise ? QStringLiteral("τ_rise")
                                                                   : QStringLiteral("τ_max");
    p.setPen(QColor(0x22, 0x22, 0x22));
    const double lh = labelLine(this->font());
    p.drawText(QRectF(4, 2, width() - 8, lh), Qt::AlignLeft | Qt::AlignVCenter,
               surface ? QStringLiteral("Where am I?  γc = %1/τc over A and f").arg(ref)
                       : QStringLiteral("τc against A at f = %1 Hz")
                             .arg(current_.params.frequencyHz, 0, 'g', 4));
    const MapRange& R = current_.range;
    const bool ready = hasMap_ && map_.mode == current_.mode;
    double tMax = 1.0; // slice: the largest collapse time, with room above
    if (ready && !surface)
        for (const auto& pt : map_.sweep.points)
            if (pt.outcome == Outcome::Collapsed) tMax = std::max(tMax, 1.1 * pt.tauC);
    const Plot pl = surface ? Plot{plotRect(), R.fMin, R.fMax, R.aMin, R.aMax, lh}
                            : Plot{plotRect(), R.aMin, R.aMax, 0.0, tMax, lh};
    if (ready && surface)
        paintSurfaceCells(p, pl, map_);
    else if (ready)
        paintSlice(p, pl, map_);
    else {
        p.setPen(QColor(0x77, 0x77, 0x77));
        p.drawText(pl.r, Qt::AlignCenter, tr("computing…"));
    }
    paintAxes(p, pl, surface);
    paintMarker(p, pl, current_.params, surface);
}

void SurfaceMarker::mousePressEvent(QMouseEvent* e) {
    const QRectF r = plotRect();
    if (e->button() != Qt::LeftButton || !r.contains(e->position())) return;
    const double u = (e->position().x() - r.left()) / r.width();
    const double v = (r.bottom() - e->position().y()) / r.height();
    if (current_.mode == MapMode::Surface)
        emit pointPicked(current_.range.aMin + v * (current_.range.aMax - current_.range.aMin),
                         current_.range.fMin + u * (current_.range.fMax - current_.range.fMin));
    else
        emit pointPicked(current_.range.aMin + u * (current_.range.aMax - current_.range.aMin),
                         current_.params.frequencyHz);
}

} // namespace kinstab::ui
