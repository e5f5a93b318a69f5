// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Min/max decimation of a sampled series for plotting: the record preview's charts and the
// report's time-history figures draw a 42 000-point record from about a thousand points.

#include <QList>
#include <QPointF>

#include <vector>

namespace kinstab::report {

// About `buckets` pairs of points: each bucket keeps its minimum and maximum, so every peak
// stays visible.
QList<QPointF> decimatedSeries(const std::vector<double>& y, double dt, int buckets,
                               bool absolute = false);

} // namespace kinstab::report
