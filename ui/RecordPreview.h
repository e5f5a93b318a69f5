// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A preview of an accelerogram for record import (docs/theory.md §7; docs/user-guide.md; paper
// Figs. 25-27): the ground record, the floor motion through the floor filter with |floor acc| and
// its fitted envelope, and the normalized Fourier amplitude spectra of both. Standalone: the main
// window docks it.

#include "core/excitation/EnvelopeFit.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/RecordMetrics.h"
#include "core/records/RecordReader.h"
#include "report/DecimatedSeries.h"

#include <QWidget>
#include <optional>

class QChart;
class QChartView;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QLineSeries;

namespace kinstab::ui {

class RecordPreview : public QWidget {
    Q_OBJECT
public:
    explicit RecordPreview(QWidget* parent = nullptr);

    // Reads a file (also ":/records/..." resources); false with errorText() set when it is broken.
    bool loadFile(const QString& path, const RecordReadOptions& options = {});
    void setRecord(const Accelerogram& ground);
    void clear(); // no record: empty charts
    void setFloorFilter(std::optional<FloorFilterParams> filter);
    // A planar project takes the record as the slab's vertical base motion, unfiltered: the
    // floor filter (a horizontal floor's response) is then switched off and locked.
    void setPlanarBase(bool planar);

    const std::optional<Accelerogram>& record() const { return ground_; }
    const std::optional<Accelerogram>& floorMotion() const { return floor_; }
    std::optional<FloorFilterParams> floorFilter() const;
    const std::optional<EnvelopeFit>& envelope() const { return fit_; }
    // The ground record's catalogue numbers, Sa at the period T shown (the building's).
    const std::optional<RecordMetrics>& metrics() const { return metrics_; }
    QString errorText() const { return error_; }

    // The shipped stand-in for the paper's Pacoima Dam vertical, and the note the UI shows with it.
    static QString defaultVerticalRecord();
    static QString defaultVerticalNote();
    // The file dialog's filter for accelerograms.
    static QString fileDialogFilter();

    QChart* groundChart() const;
    QChart* floorChart() const;
    QChart* spectrumChart() const;

signals:
    void recordChanged();

private:
    void rebuild();
    void plotGround();
    void plotFloor();
    void plotSpectra();
    void showInfo();

    std::optional<Accelerogram> ground_, floor_;
    std::optional<EnvelopeFit> fit_;
    std::optional<RecordMetrics> metrics_;
    QString error_;
    QLabel* info_ = nullptr;
    QCheckBox* filterOn_ = nullptr;
    bool planarBase_ = false;
    QDoubleSpinBox* period_ = nullptr;
    QDoubleSpinBox* damping_ = nullptr;
    QChartView* groundView_ = nullptr;
    QChartView* floorView_ = nullptr;
    QChartView* spectrumView_ = nullptr;
};

} // namespace kinstab::ui
