// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/ChartMenu.h"

#include "ui/ChartExport.h"
#include "ui/NiceAxisTicks.h"
#include "ui/ProjectFolder.h"

#include <QApplication>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QRegularExpression>

namespace kinstab::ui {

namespace {

QImage chartImage(QChartView* view) {
    QImage img(view->size() * 2, QImage::Format_ARGB32);
    img.setDevicePixelRatio(2);
    img.fill(Qt::white);
    QPainter p(&img);
    p.setRenderHint(QPainter::Antialiasing);
    view->render(&p);
    return img;
}

void saveImage(QChartView* view) {
    QString name = view->chart()->title().section(QLatin1Char(' '), 0, 2).simplified();
    name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("-"));
    const QString path = QFileDialog::getSaveFileName(
        view, QObject::tr("Save chart image"),
        inOpenProjectFolder((name.isEmpty() ? QStringLiteral("chart") : name) + ".png"),
        QObject::tr("PNG image (*.png);;SVG vector (*.svg)"));
    if (path.isEmpty()) return;
    if (const QString e = exportChart(view, path); !e.isEmpty())
        QMessageBox::warning(view, QObject::tr("Save chart image"), e);
}

// Context-menu events reach a chart's viewport: the view is its parent.
class ChartMenuFilter : public QObject {
public:
    using QObject::QObject;
    bool eventFilter(QObject* watched, QEvent* e) override {
        if (e->type() == QEvent::ContextMenu) {
            auto* view = qobject_cast<QChartView*>(watched->parent());
            if (view && view->viewport() == watched &&
                view->contextMenuPolicy() == Qt::DefaultContextMenu) {
                QMenu* menu = chartMenu(view);
                menu->setAttribute(Qt::WA_DeleteOnClose);
                menu->popup(static_cast<QContextMenuEvent*>(e)->globalPos());
                return true;
            }
        }
        // Charts get their 1-2-5 ticks when first shown (their axes exist by then). When ticks
        // or labels move, QtCharts repaints only the new label items: under a window manager the
        // old labels stayed on screen beside the new ones (ghost ticks and titles). A chart is
        // small, so the whole viewport is repainted on every change.
        if (e->type() == QEvent::Show)
            if (auto* view = qobject_cast<QChartView*>(watched)) {
                view->setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
                useNiceTicks(view->chart());
            }
        return false;
    }
};

} // namespace

QMenu* chartMenu(QChartView* view) {
    auto* menu = new QMenu(view);
    QAction* save = menu->addAction(QObject::tr("Save image…"));
    save->setObjectName(QStringLiteral("saveChartImage"));
    QObject::connect(save, &QAction::triggered, view, [view] { saveImage(view); });
    QAction* copy = menu->addAction(QObject::tr("Copy image"));
    copy->setObjectName(QStringLiteral("copyChartImage"));
    QObject::connect(copy, &QAction::triggered, view,
                     [view] { QApplication::clipboard()->setImage(chartImage(view)); });
    return menu;
}

void installChartMenus() {
    static ChartMenuFilter* filter = nullptr;
    if (filter || !qApp) return;
    filter = new ChartMenuFilter(qApp);
    qApp->installEventFilter(filter);
}

} // namespace kinstab::ui
