// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The animated side view of the block (painted by paintBlockScene), and its two traces,
// theta/alpha and the base acceleration against time with the cursor: click or drag to scrub.

#include "ui/teaching/BlockPainter.h"

#include <QWidget>

namespace kinstab::ui {

class BlockRun;

class BlockAnimation : public QWidget {
    Q_OBJECT
public:
    explicit BlockAnimation(QWidget* parent = nullptr);
    void setScene(const BlockScene& scene);
    const BlockScene& scene() const { return scene_; }
    QSize sizeHint() const override { return {760, 360}; }
    QSize minimumSizeHint() const override { return {360, 180}; }

protected:
    void paintEvent(QPaintEvent*) override;

private:
    BlockScene scene_;
};

class BlockTraces : public QWidget {
    Q_OBJECT
public:
    explicit BlockTraces(QWidget* parent = nullptr);
    void setRun(const BlockRun* run); // must outlive its display here
    void setCursor(double t);
    QSize sizeHint() const override { return {760, 220}; }
    QSize minimumSizeHint() const override { return {360, 130}; }

signals:
    void seekRequested(double t);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;

private:
    double timeAt(double x) const;
    const BlockRun* run_ = nullptr;
    double cursor_ = 0;
};

} // namespace kinstab::ui
