// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The record half of the Excitation panel (docs/theory.md §7; docs/user-guide.md): an accelerogram
// file with a preview (ground, floor through the floor filter, spectra: RecordPreview, whose
// floor-filter switch, T and zeta are the excitation's), and the peak (g) the motion under the slab
// is scaled to. A file that cannot be read shows its reason beside the file field.

#include "core/excitation/RecordExcitation.h"

#include <QWidget>

#include <optional>

class QLabel;
class QLineEdit;
class QPushButton;

namespace kinstab::ui {

class NumberField;
class RecordPreview;

class RecordInput : public QWidget {
    Q_OBJECT
public:
    explicit RecordInput(QWidget* parent = nullptr);

    // Reads the file into the preview; false (reason beside the field) when it cannot be read.
    bool loadFile(const QString& path);
    // A readable file is loaded and the peak field is valid.
    bool isReady() const;
    QString problem() const; // why not ready ("" when ready)
    // The excitation the inputs describe (file, floor filter, scaling); none until a file loads.
    std::optional<RecordExcitation> record() const;
    void setRecord(const RecordExcitation& e);

    // The last run's result (or why it failed, in red) under the inputs.
    void setResult(const QString& text, bool error);
    QString resultText() const;
    // Greys the result with "inputs changed — Run to update" above it (ui/ResultState.h).
    void setResultStale(bool stale);

    NumberField* peakField() const { return m_peak; }
    RecordPreview* preview() const { return m_preview; }
    QLabel* fileMessage() const { return m_message; }
    QLineEdit* fileEdit() const { return m_file; }

public slots:
    void chooseFile();

signals:
    void changed();

private:
    void showError(const QString& text);
    void showResult();

    QLineEdit* m_file;
    QPushButton* m_browse;
    QLabel* m_message;
    QLabel* m_result;
    QString m_resultText;
    bool m_resultError = false;
    bool m_resultStale = false;
    NumberField* m_peak;
    RecordPreview* m_preview;
    RecordReadOptions m_read; // the hints of the loaded project (headerless text)
    double m_scaleFactor = 1.0;
    bool m_loaded = false;
};

} // namespace kinstab::ui
