// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Base of the input panels: a form of checked fields. A panel is valid when all its fields are;
// MainWindow disables Run while any panel is not.

#include <QWidget>

#include <vector>

class QFormLayout;

namespace kinstab::ui {

class NumberField;

class InputPanel : public QWidget {
    Q_OBJECT
public:
    explicit InputPanel(QWidget* parent = nullptr);

    bool isValid() const;
    // The NumberFields alone, without extraProblems().
    bool fieldsValid() const;
    // "Label: reason" for every invalid field, for the status bar.
    QStringList problems() const;

signals:
    void changed(); // any input changed (valid or not)

protected:
    // Adds a labelled, checked field to the form and tracks it.
    // `name` becomes the field's objectName (tests, settings).
    NumberField* addField(const QString& name, const QString& label, const QString& unit,
                          const QString& toolTip);
    // Tracks a field placed elsewhere in the form.
    void track(NumberField* field, const QString& label);
    QFormLayout* form() const { return m_form; }
    // Problems of inputs that are not NumberFields ("Label: reason"); they gate Run too.
    virtual QStringList extraProblems() const { return {}; }

private:
    QFormLayout* m_form;
    std::vector<std::pair<NumberField*, QString>> m_fields;
};

} // namespace kinstab::ui
