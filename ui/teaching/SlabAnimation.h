// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The animated side view of the slab on its walls (painted by paintSlabScene).

#include "ui/teaching/SlabPainter.h"

#include <QWidget>

namespace kinstab::ui {

class SlabAnimation : public QWidget {
    Q_OBJECT
public:
    explicit SlabAnimation(QWidget* parent = nullptr);
    void setScene(const SlabScene& scene);
    const SlabScene& scene() const { return scene_; }
    QSize sizeHint() const override { return {760, 360}; }
    // 180 px still draws the header, the walls and the ruler; with the traces and the play bar
    // it fits the Teaching tab at 1280 × 800 (about 400 px tall).
    QSize minimumSizeHint() const override { return {360, 180}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    SlabScene scene_;
};

} // namespace kinstab::ui
