// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The friction-law calibration panel (Furgerson 1980 ch. III, docs/theory.md §8): load triplet
// shear tests (CSV, or the paper's Table 1 built in), see the test curves and fitted decay laws per
// confining pressure (Figs. 18-20), V_inf or tau_inf against CP with the Coulomb line (Fig. 21),
// the table of fits, and send the resulting mu_inf to the stability model ("Use this mu").
// Self-contained: the main window only docks it and connects useMu.

#include "core/friction/FrictionCalibration.h"
#include "ui/Units.h"

#include <QWidget>

#include <optional>

class QChartView;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLayout;
class QPushButton;
class QTableWidget;
class QChart;

namespace kinstab::ui {

class FrictionPanel : public QWidget {
    Q_OBJECT
public:
    // Starts with the built-in Table 1 (:/data/furgerson1980/table1_triplet_tests.csv).
    explicit FrictionPanel(QWidget* parent = nullptr);

    // Replaces the data; false (and the message shown in the panel) when the file is refused.
    bool loadCsv(const QString& path, QString* error = nullptr);
    void setRuns(const std::vector<TripletCurve>& runs, const QString& sourceName);

    void setConfiguration(const QString& configuration);
    void setBearingArea(double in2); // 0: not set (no mu_inf)
    double bearingAreaIn2() const { return areaIn2_; }
    // kip, psi, in, in² (US) or kN, kPa, mm, cm² (SI); the data stay in the paper's US units.
    void setUnitSystem(UnitSystem s);
    void setWithIntercept(bool withIntercept);

    // mu_inf of the selected configuration, when a bearing area is set.
    std::optional<double> currentMu() const;
    const FrictionCalibration& calibration() const { return calibration_; }
    QString sourceName() const { return source_; }
    int tableRows() const;

signals:
    void useMu(double mu);

private:
    void buildUi();
    QLayout* buildControls(QPushButton* open);
    QLayout* buildMuRow();
    QWidget* buildResults();
    void recalibrate();
    void refresh();
    void fillCurveChart();
    void fillCoulombChart();
    void fillTable();
    void openFile();

    std::vector<TripletCurve> runs_;
    FrictionCalibration calibration_;
    QString source_;
    QComboBox* configuration_ = nullptr;
    QComboBox* slopeKind_ = nullptr;
    QDoubleSpinBox* area_ = nullptr;
    QPushButton* useMu_ = nullptr;
    QLabel* muLabel_ = nullptr;
    QLabel* status_ = nullptr;
    QChartView* curves_ = nullptr;
    QChartView* coulomb_ = nullptr;
    QTableWidget* table_ = nullptr;
    UnitSystem units_ = UnitSystem::US;
    double areaIn2_ = 0.0; // A_b as set or typed: a switch of units re-shows, never rounds it
};

} // namespace kinstab::ui
