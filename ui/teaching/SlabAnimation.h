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
    QSize minimumSizeHint() const override { return {360, 200}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    SlabScene scene_;
};

} // namespace kinstab::ui
