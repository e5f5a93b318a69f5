// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Undo/redo for the input panels: every change of the inputs becomes one step on a QUndoStack,
// holding the inputs before and after as text (the project JSON). Keystrokes into one field in
// quick succession merge into one step. The stack's clean state is the saved file, so "modified"
// is !isClean(). Undo and redo load a snapshot back into the panels through restore(); the
// changes that loading causes are not recorded again.

#include <QObject>
#include <QPointer>

#include <functional>
#include <string>

class QUndoStack;

namespace kinstab::ui {

class InputHistory : public QObject {
    Q_OBJECT
public:
    // snapshot: the inputs now, or "" while a field is invalid (nothing is recorded then).
    // restore: loads a snapshot into the panels.
    InputHistory(std::function<std::string()> snapshot,
                 std::function<void(const std::string&)> restore, QObject* parent = nullptr);

    QUndoStack* stack() const { return m_stack; }
    // The inputs now are a fresh start (New, Open): no history, not modified.
    void reset();
    // The inputs now are what is on disk (Save).
    void markSaved();
    bool isModified() const;
    // Called after every input change: records a step if the inputs differ from the last ones.
    void recordChange();

    // Ctrl+Z / Ctrl+Shift+Z inside a text field of `scope` undo the inputs, not the field's text.
    void claimUndoKeys(QWidget* scope);

    static constexpr int mergeWindowMs = 1500; // keystrokes closer than this are one step

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    friend class InputEdit;
    void load(const std::string& snapshot);

    std::function<std::string()> m_snapshot;
    std::function<void(const std::string&)> m_restore;
    QUndoStack* m_stack;
    std::string m_last; // the inputs after the last step (or the reset)
    bool m_loading = false;
    QPointer<QWidget> m_scope;
};

} // namespace kinstab::ui
