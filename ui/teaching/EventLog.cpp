// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/EventLog.h"

#include "ui/teaching/StateStyle.h"

#include <QEvent>
#include <QHeaderView>

namespace kinstab::ui {

void EventLogModel::setEvents(std::vector<SlabEvent> events, double tstar) {
    beginResetModel();
    events_ = std::move(events);
    tstar_ = tstar;
    current_ = -1;
    endResetModel();
}

void EventLogModel::setCurrent(int row) {
    if (row == current_) return;
    const int old = current_;
    current_ = row;
    if (old >= 0 && old < rowCount())
        emit dataChanged(index(old, 0), index(old, columnCount() - 1));
    if (row >= 0 && row < rowCount())
        emit dataChanged(index(row, 0), index(row, columnCount() - 1));
}

int EventLogModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(events_.size());
}

int EventLogModel::columnCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : 4;
}

QVariant EventLogModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const SlabEvent& e = events_[static_cast<std::size_t>(index.row())];
    const DisplayState s = displayStateOf(e.kind);
    if (role == Qt::DisplayRole) {
        switch (index.column()) {
        case 0:
            return QString::number(e.tau, 'f', 3);
        case 1:
            return QString::number(e.tau * tstar_, 'f', 3);
        case 2:
            return stateLabel(s, e.direction);
        case 3:
            return QString::number(e.delta, 'f', 4);
        }
    }
    if (role == Qt::ForegroundRole && index.column() == 2) return stateColor(s);
    if (role == Qt::BackgroundRole && index.row() == current_) return QColor(0xff, 0xf0, 0xb3);
    if (role == Qt::TextAlignmentRole)
        return index.column() == 2 ? int(Qt::AlignLeft | Qt::AlignVCenter)
                                   : int(Qt::AlignRight | Qt::AlignVCenter);
    return {};
}

QVariant EventLogModel::headerData(int section, Qt::Orientation o, int role) const {
    if (role != Qt::DisplayRole) return {};
    if (o == Qt::Vertical) return section + 1;
    switch (section) {
    case 0:
        return tr("τ");
    case 1:
        return tr("t [s]");
    case 2:
        return tr("event");
    case 3:
        return tr("δ [d/2]");
    }
    return {};
}

EventLog::EventLog(QWidget* parent) : QTableView(parent), model_(new EventLogModel(this)) {
    setModel(model_);
    setSelectionMode(QAbstractItemView::NoSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
    setToolTip(tr("Click an event to jump there"));
    connect(this, &QTableView::clicked, this,
            [this](const QModelIndex& i) { emit eventClicked(i.row()); });
}

void EventLog::setEvents(std::vector<SlabEvent> events, double tstar) {
    model_->setEvents(std::move(events), tstar);
}

void EventLog::setCurrent(int row) {
    model_->setCurrent(row);
    if (row >= 0 && row < model_->rowCount())
        scrollTo(model_->index(row, 0), QAbstractItemView::EnsureVisible);
}

void EventLog::changeEvent(QEvent* e) {
    QTableView::changeEvent(e);
    if (e->type() == QEvent::FontChange)
        verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 4);
}

} // namespace kinstab::ui
