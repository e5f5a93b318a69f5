// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The run's event list (time, kind, delta); the event the clock last reached is highlighted,
// and a click on a row asks to jump there.

#include "core/slab/SlabTypes.h"

#include <QAbstractTableModel>
#include <QTableView>

#include <vector>

namespace kinstab::ui {

class EventLogModel : public QAbstractTableModel {
    Q_OBJECT
public:
    using QAbstractTableModel::QAbstractTableModel;
    void setEvents(std::vector<SlabEvent> events, double tstar);
    void setCurrent(int row);
    int current() const { return current_; }
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;

private:
    std::vector<SlabEvent> events_;
    double tstar_ = 0.099;
    int current_ = -1;
};

class EventLog : public QTableView {
    Q_OBJECT
public:
    explicit EventLog(QWidget* parent = nullptr);
    void setEvents(std::vector<SlabEvent> events, double tstar);
    void setCurrent(int row); // highlights and scrolls to the row (-1: none)
    EventLogModel* logModel() const { return model_; }

signals:
    void eventClicked(int index);

protected:
    void changeEvent(QEvent* e) override; // rows follow the font (presentation mode)

private:
    EventLogModel* model_;
};

} // namespace kinstab::ui
