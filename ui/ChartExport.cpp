// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ChartExport.h"

#include "ui/AtomicSave.h"

#include <QBuffer>
#include <QChart>
#include <QChartView>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>

namespace kinstab::ui {

QString exportChart(QChartView* view, const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const QSize size = view->size();
    if (suffix == QLatin1String("svg")) {
        QByteArray bytes; // in memory, then written whole (ui/AtomicSave.h)
        QBuffer buffer(&bytes);
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(view->chart()->title());
        svg.setDescription(QStringLiteral("kinstab chart"));
        QPainter p;
        if (!p.begin(&svg)) return QObject::tr("%1: cannot write SVG").arg(path);
        view->render(&p);
        p.end();
        return saveAtomically(path, bytes);
    }
    if (suffix != QLatin1String("png")) return QObject::tr("%1: use .png or .svg").arg(path);
    QImage img(size * 2, QImage::Format_ARGB32);
    img.setDevicePixelRatio(2);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    view->render(&p);
    p.end();
    return saveImageAtomically(path, img, "PNG");
}

} // namespace kinstab::ui
