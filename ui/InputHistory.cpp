// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/InputHistory.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QDateTime>
#include <QKeyEvent>
#include <QLineEdit>
#include <QUndoCommand>
#include <QUndoStack>
#include <QWidget>

namespace kinstab::ui {

// One change of the inputs: the snapshots before and after, and the field it was typed into.
class InputEdit : public QUndoCommand {
public:
    InputEdit(InputHistory* h, std::string before, std::string after, const QObject* field)
        : m_history(h), m_before(std::move(before)), m_after(std::move(after)), m_field(field),
          m_at(QDateTime::currentMSecsSinceEpoch()) {
        setText(QObject::tr("edit"));
    }
    int id() const override { return 1; }
    // The state is already there when the edit is pushed: the first redo does nothing.
    void redo() override {
        if (m_pushed) m_history->load(m_after);
        m_pushed = true;
    }
    void undo() override { m_history->load(m_before); }
    bool mergeWith(const QUndoCommand* other) override {
        const auto* o = static_cast<const InputEdit*>(other);
        if (!m_field || o->m_field != m_field || o->m_at - m_at > InputHistory::mergeWindowMs)
            return false;
        m_after = o->m_after;
        m_at = o->m_at;
        setObsolete(m_after == m_before); // typed and deleted again: no step at all
        return true;
    }

private:
    InputHistory* m_history;
    std::string m_before, m_after;
    const QObject* m_field; // the text field typed into (null: not typing)
    qint64 m_at;
    bool m_pushed = false;
};

InputHistory::InputHistory(std::function<std::string()> snapshot,
                           std::function<void(const std::string&)> restore, QObject* parent)
    : QObject(parent), m_snapshot(std::move(snapshot)), m_restore(std::move(restore)),
      m_stack(new QUndoStack(this)) {}

void InputHistory::reset() {
    m_stack->clear();
    m_last = m_snapshot();
}

void InputHistory::markSaved() {
    m_stack->setClean();
}

bool InputHistory::isModified() const {
    return !m_stack->isClean();
}

void InputHistory::recordChange() {
    if (m_loading) return;
    std::string now = m_snapshot();
    if (now.empty() || now == m_last) return;
    // Only typing merges: the focus is in a text field (a click on a box or a list is a step).
    QWidget* focus = QApplication::focusWidget();
    const bool typing = qobject_cast<QLineEdit*>(focus) || qobject_cast<QAbstractSpinBox*>(focus);
    m_stack->push(new InputEdit(this, m_last, now, typing ? focus : nullptr));
    m_last = std::move(now);
}

void InputHistory::load(const std::string& snapshot) {
    m_loading = true;
    m_restore(snapshot);
    m_loading = false;
    m_last = snapshot;
}

void InputHistory::claimUndoKeys(QWidget* scope) {
    m_scope = scope;
    qApp->installEventFilter(this);
}

// A text field takes Ctrl+Z for its own text (a ShortcutOverride it accepts); inside the scope
// the key is left to the window's Undo/Redo actions instead, so it undoes whole input steps.
bool InputHistory::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride || !m_scope) return false;
    auto* w = qobject_cast<QWidget*>(watched);
    if (!w || !m_scope->isAncestorOf(w)) return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
        event->ignore();
        return true;
    }
    return false;
}

} // namespace kinstab::ui
