// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A frame around a result view that can mark it stale: the view is dimmed and a line above it
// says "inputs changed — Run to update", until the view shows a result of the current inputs.

#include <QWidget>

class QLabel;

namespace kinstab::ui {

class StaleFrame : public QWidget {
    Q_OBJECT
public:
    explicit StaleFrame(QWidget* view, QWidget* parent = nullptr);

    void setStale(bool stale);
    bool isStale() const { return m_stale; }
    QWidget* view() const { return m_view; }

    // The line shown above a stale result (also used by the 3D surface view).
    static QString staleText();
    static QString staleStyle();

private:
    QWidget* m_view;
    QLabel* m_line;
    QWidget* m_veil; // a translucent white sheet over the view (mouse events pass through)
    bool m_stale = false;
};

} // namespace kinstab::ui
