#include "ui/ChartExport.h"

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
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(view->chart()->title());
        svg.setDescription(QStringLiteral("kinstab chart"));
        QPainter p;
        if (!p.begin(&svg)) return QObject::tr("%1: cannot write SVG").arg(path);
        view->render(&p);
        p.end();
        return {};
    }
    if (suffix != QLatin1String("png")) return QObject::tr("%1: use .png or .svg").arg(path);
    QImage img(size * 2, QImage::Format_ARGB32);
    img.setDevicePixelRatio(2);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    view->render(&p);
    p.end();
    return img.save(path) ? QString() : QObject::tr("%1: cannot write PNG").arg(path);
}

} // namespace kinstab::ui
