// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/BlockMapView.h"

#include "ui/BackgroundJob.h"
#include "ui/OverturningMapPlot.h"
#include "ui/StaleFrame.h"

#include <QElapsedTimer>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>
#include <numbers>

namespace kinstab::ui {

namespace {
QString equationsText(RockingEquations e) {
    return e == RockingEquations::Exact ? BlockMapView::tr("exact")
                                        : BlockMapView::tr("linearised");
}
QString shapeText(PulseShape s) {
    const std::string_view n = pulseShapeName(s);
    return QString::fromUtf8(n.data(), static_cast<int>(n.size()));
}
// The settings that decide the map (not whether the block is the model shown).
BlockMapSettings mapPart(BlockMapSettings s) {
    s.selected = true;
    return s;
}
} // namespace

QString blockMapTitle(const BlockMapSettings& s) {
    return BlockMapView::tr("%1 pulse, %2 equations")
        .arg(shapeText(s.shape), equationsText(s.equations));
}

BlockMapResult computeBlockMaps(const BlockMapSettings& s, JobContext& job) {
    BlockMapResult r;
    r.settings = mapPart(s);
    const OverturningMapSpec spec = blockMapSpec(s);
    const std::size_t n = static_cast<std::size_t>(s.points) * static_cast<std::size_t>(s.points);
    job.total = 2 * n;
    // Worker threads report (done, n) of one map; the second map counts on from n. The hook is
    // replaced only between the two maps, while no worker runs.
    job.control.onProgress = [&job](std::size_t d, std::size_t) { job.done = d; };
    r.main = overturningMap(blockMapModel(s), spec, &job.control);
    if (!r.main.complete) return r;
    job.control.onProgress = [&job, n](std::size_t d, std::size_t) { job.done = n + d; };
    OverturningMap other = overturningMap(otherEquationsModel(s), spec, &job.control);
    job.control.onProgress = nullptr;
    if (other.complete) r.other = std::move(other);
    return r;
}

BlockMapView::BlockMapView(QWidget* parent)
    : QWidget(parent), m_plot(new OverturningMapPlot), m_header(new QLabel(this)),
      m_readout(new QLabel(this)), m_job(new BackgroundJob(this)) {
    setObjectName(QStringLiteral("blockMapView"));
    m_frame = new StaleFrame(m_plot, this);
    m_header->setWordWrap(true);
    m_header->setTextFormat(Qt::PlainText);
    m_readout->setObjectName(QStringLiteral("blockMapReadout"));
    m_readout->setTextFormat(Qt::PlainText);
    m_readout->setWordWrap(true);
    m_readout->setMinimumHeight(2 * fontMetrics().height());
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(6, 6, 6, 6);
    v->addWidget(m_header);
    v->addWidget(m_frame, 1);
    v->addWidget(m_readout);
    connect(m_plot, &OverturningMapPlot::hovered, this,
            [this](int i, int j) { m_readout->setText(readout(i, j)); });
    connect(m_job, &BackgroundJob::progress, this, &BlockMapView::progress);
    connect(m_job, &BackgroundJob::failed, this,
            [this](const QString& e) { emit finished(false, e); });
    updateHeader();
}

void BlockMapView::run(const BlockMapSettings& s) {
    if (const InputProblem p = checkBlockMapSettings(s); !p.empty()) {
        emit finished(false, QString::fromStdString(describe(p)));
        return;
    }
    const qint64 total = 2LL * s.points * s.points;
    auto clock = std::make_shared<QElapsedTimer>();
    clock->start();
    m_job->start<BlockMapResult>(
        [s](JobContext& c) { return computeBlockMaps(s, c); },
        [this, clock](BlockMapResult r) {
            const bool complete = r.main.complete && r.other.has_value();
            const QString done = tr("Done: 2 × %1 points in %2 s")
                                     .arg(r.main.overturns.size())
                                     .arg(clock->elapsed() / 1000.0, 0, 'f', 2);
            if (complete) deliver(std::move(r));
            emit finished(complete,
                          complete ? done : tr("Cancelled: the map shown is the one before"));
        });
    emit started(total);
}

void BlockMapView::cancel() {
    m_job->cancel();
}

void BlockMapView::clear() {
    m_job->cancel();
    m_result.reset();
    m_plot->clear();
    m_readout->clear();
    updateHeader();
    setInputs(m_inputs);
}

bool BlockMapView::isRunning() const {
    return m_job->isRunning();
}

void BlockMapView::deliver(BlockMapResult r) {
    m_result = std::move(r);
    const BlockMapSettings& s = m_result->settings;
    m_plot->setMaps(m_result->main, m_result->other, equationsText(s.equations),
                    equationsText(otherEquationsModel(s).equations));
    updateHeader();
    setInputs(m_inputs);
}

void BlockMapView::setInputs(const BlockMapSettings& s) {
    m_inputs = s;
    m_frame->setStale(isStale());
}

bool BlockMapView::isStale() const {
    return m_result && !(m_result->settings == mapPart(m_inputs));
}

void BlockMapView::setUnitSystem(UnitSystem s) {
    m_units = s;
    updateHeader();
}

void BlockMapView::updateHeader() {
    if (!m_result) {
        m_header->setText(tr("Overturning map of the free-standing block: set its inputs in the "
                             "Model panel and Run."));
        return;
    }
    const BlockMapSettings& s = m_result->settings;
    const RockingModel m = blockMapModel(s);
    auto len = [this](double metres) {
        return QString::fromStdString(lengthText(metres, m_units, LengthScale::Structure) + " " +
                                      lengthUnitSymbol(m_units, LengthScale::Structure));
    };
    m_header->setText(
        tr("Overturning map: %1. b = %2, h = %3 (α = %4 rad, p = %5 rad/s), η = %6, μ = %7; "
           "%8 × %8 points. Dashed: the %9 equations' boundary.")
            .arg(blockMapTitle(s), len(s.block.halfWidth), len(s.block.halfHeight))
            .arg(blockAlpha(s.block), 0, 'f', 4)
            .arg(blockFrequency(s.block), 0, 'f', 3)
            .arg(restitutionOf(m), 0, 'f', 3)
            .arg(s.mu ? QString::number(*s.mu) : tr("none (no sliding)"))
            .arg(s.points)
            .arg(equationsText(otherEquationsModel(s).equations)));
}

QString BlockMapView::readout(int i, int j) const {
    if (!m_result || i < 0 || j < 0) return QString();
    const OverturningMap& m = m_result->main;
    if (i >= static_cast<int>(m.frequencies.size()) || j >= static_cast<int>(m.amplitudes.size()))
        return QString();
    const BlockMapSettings& s = m_result->settings;
    const double alpha = blockAlpha(s.block), p = blockFrequency(s.block);
    auto fate = [](const OverturningMap& map, std::size_t k) {
        if (map.overturns[k] == 1) return tr("overturns");
        if (map.overturns[k] == 2) return tr("leaves the base");
        return tr("survives, max |θ|/α = %1").arg(map.maxThetaOverAlpha[k], 0, 'f', 3);
    };
    const std::size_t k = m.at(i, j);
    QString text = tr("ω_p/p = %1, a_p/(αg) = %2 (f_p = %3 Hz, a_p = %4 g): %5 (%6)")
                       .arg(m.frequencies[i], 0, 'f', 3)
                       .arg(m.amplitudes[j], 0, 'f', 3)
                       .arg(m.frequencies[i] * p / (2 * std::numbers::pi), 0, 'f', 3)
                       .arg(m.amplitudes[j] * alpha, 0, 'f', 3)
                       .arg(fate(m, k), equationsText(s.equations));
    if (m_result->other)
        text +=
            tr("; %1 (%2)")
                .arg(fate(*m_result->other, k), equationsText(otherEquationsModel(s).equations));
    return text;
}

QString BlockMapView::readoutText() const {
    return m_readout->text();
}

} // namespace kinstab::ui
