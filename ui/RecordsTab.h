// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Records tab: import an accelerogram (AT2, COSMOS, CSMIP, text) and preview the ground
// motion, the floor motion through the floor filter, the spectra and the fitted envelope
// (paper Figs. 25-27). It shows the open project's record with its floor filter, a planar
// project's vertical motion, or says that the project has none.

#include <QWidget>

#include "core/io/Project.h"

class QLabel;

namespace kinstab::ui {

class RecordPreview;

class RecordsTab : public QWidget {
    Q_OBJECT
public:
    explicit RecordsTab(QWidget* parent = nullptr);
    // Loads a file; on failure the reason is shown beside the button and false returned.
    bool open(const QString& path);
    // The project's record and floor filter, a planar project's vertical motion (unfiltered),
    // or an empty state that says why.
    void showProject(const Project& p);
    QString messageText() const;
    RecordPreview* preview() const { return m_preview; }
    QString errorText() const;

public slots:
    void chooseFile();

private:
    RecordPreview* m_preview;
    QLabel* m_message;
};

} // namespace kinstab::ui
