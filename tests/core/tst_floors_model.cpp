// SPDX-License-Identifier: GPL-3.0-or-later
// The shear-building model of the floor-motion check:
//  - 2 levels against the closed form of the 2-DOF frequency equation
//    m1 m2 w^4 - (m1 k2 + m2 (k1 + k2)) w^2 + k1 k2 = 0 and its mode shapes;
//  - modes orthogonal to the mass, sum_r Gamma_r phi_r = 1, first period = T (both profiles);
//  - a 1-level model under a record equals the SDOF floor filter (same recurrence);
//  - floor accelerations against an independent RK4 integration of the full MDOF equations
//    M u'' + C u' + K u = -M 1 a_g (C the classical damping matrix of the modal ratios),
//    to 1e-6 of the peak.

#include "core/building/FloorMotions.h"
#include "core/building/ModalModel.h"
#include "core/building/ShearBuilding.h"
#include "core/excitation/FloorFilter.h"
#include "core/records/RecordReader.h"

#include <QtTest>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace kinstab;

namespace {

const std::string kRecords = KINSTAB_SOURCE_DIR "/resources/records/";

Building building(int stories, double period, std::vector<double> weights = {},
                  std::vector<double> heights = {}) {
    Building b;
    b.stories = stories;
    b.height = heights.empty() ? 12.0 * stories : 0.0;
    for (double h : heights)
        b.height += h;
    b.period = period;
    b.storyWeights = std::move(weights);
    b.storyHeights = std::move(heights);
    return b;
}

// The first `seconds` of the Pacoima Dam 164 record (NGA RSN77), the paper's record.
Accelerogram pacoima(double seconds) {
    Accelerogram a = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    a.samples.resize(std::min(a.samples.size(), static_cast<std::size_t>(seconds / a.dt) + 1));
    return a;
}

} // namespace

class TestFloorsModel : public QObject {
    Q_OBJECT
private slots:
    void twoLevelsMatchClosedForm();
    void modesAreMassOrthogonalAndComplete_data();
    void modesAreMassOrthogonalAndComplete();
    void oneLevelEqualsFloorFilter();
    void matchesRk4OfTheFullSystem();
    void roofOfThePaperBuildingAgainstTheFloorFilter();
};

void TestFloorsModel::twoLevelsMatchClosedForm() {
    // Level weights 2 (bottom) and 1; "weight" profile: k1 : k2 = (2 + 1) : 1.
    const ShearBuilding s = shearBuilding(building(2, 0.5, {2.0, 1.0}), StiffnessProfile::Weight);
    const double m1 = s.masses[0], m2 = s.masses[1], k1 = s.stiffness[0], k2 = s.stiffness[1];
    QCOMPARE(m1 / m2, 2.0);
    QCOMPARE_LT(std::abs(k1 / k2 - 3.0), 1e-12);
    const double b = m1 * k2 + m2 * (k1 + k2), disc = std::sqrt(b * b - 4 * m1 * m2 * k1 * k2);
    const double w1sq = (b - disc) / (2 * m1 * m2), w2sq = (b + disc) / (2 * m1 * m2);
    const ModalModel model = modalModel(s);
    QCOMPARE(model.modes.size(), std::size_t(2));
    const double pi = std::numbers::pi;
    QCOMPARE_LT(std::abs(model.modes[0].period - 2 * pi / std::sqrt(w1sq)), 1e-12);
    QCOMPARE_LT(std::abs(model.modes[0].period - 0.5), 1e-12);
    QCOMPARE_LT(std::abs(model.modes[1].period - 2 * pi / std::sqrt(w2sq)), 1e-12);
    // Second row of (K - w^2 M) phi = 0 with phi_2 = 1: phi_1 = (k2 - w^2 m2) / k2.
    for (int r = 0; r < 2; ++r) {
        const double wsq = r == 0 ? w1sq : w2sq;
        const double phi1 = (k2 - wsq * m2) / k2;
        QCOMPARE_LT(std::abs(model.modes[r].shape[0] - phi1), 1e-10);
        QCOMPARE(model.modes[r].shape[1], 1.0);
        const double gamma = (m1 * phi1 + m2) / (m1 * phi1 * phi1 + m2);
        QCOMPARE_LT(std::abs(model.modes[r].participation - gamma), 1e-10);
    }
}

void TestFloorsModel::modesAreMassOrthogonalAndComplete_data() {
    QTest::addColumn<int>("profile");
    QTest::addColumn<bool>("uneven");
    QTest::newRow("16 levels uniform") << 0 << false;
    QTest::newRow("16 levels weight") << 1 << false;
    QTest::newRow("16 levels uneven weight") << 1 << true;
}

void TestFloorsModel::modesAreMassOrthogonalAndComplete() {
    QFETCH(int, profile);
    QFETCH(bool, uneven);
    std::vector<double> w, h;
    if (uneven)
        for (int i = 0; i < 16; ++i) {
            w.push_back(1.0 + 0.1 * (i % 5));
            h.push_back(i == 0 ? 15.0 : 10.8);
        }
    Building b = building(16, 1.0, w, h);
    if (!uneven) b.height = 177.0; // the paper's building
    const ShearBuilding s = shearBuilding(b, static_cast<StiffnessProfile>(profile));
    const ModalModel model = modalModel(s);
    QCOMPARE(model.modes.size(), std::size_t(16));
    QCOMPARE_LT(std::abs(model.modes.front().period - 1.0), 1e-12); // scaled to T
    const Eigen::MatrixXd M = massMatrix(s), K = stiffnessMatrix(s);
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(16);
    double effective = 0;
    for (std::size_t r = 0; r < 16; ++r) {
        const Eigen::Map<const Eigen::VectorXd> pr(model.modes[r].shape.data(), 16);
        sum += model.modes[r].participation * pr;
        effective += model.modes[r].effectiveMass;
        if (r > 0) QVERIFY(model.modes[r].period < model.modes[r - 1].period);
        const double mrr = pr.dot(M * pr);
        const double w2 = model.modes[r].omega * model.modes[r].omega;
        QCOMPARE_LT(std::abs(pr.dot(K * pr) / mrr - w2), 1e-9 * w2);
        for (std::size_t q = 0; q < r; ++q) {
            const Eigen::Map<const Eigen::VectorXd> pq(model.modes[q].shape.data(), 16);
            QVERIFY2(std::abs(pq.dot(M * pr)) < 1e-10 * mrr, "phi_q' M phi_r != 0");
        }
    }
    QVERIFY((sum - Eigen::VectorXd::Ones(16)).cwiseAbs().maxCoeff() < 1e-10);
    QCOMPARE_LT(std::abs(effective - 1.0), 1e-10);
}

void TestFloorsModel::oneLevelEqualsFloorFilter() {
    const Accelerogram ground = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    const ModalModel model = modalModel(shearBuilding(building(1, 1.0), StiffnessProfile::Uniform));
    const std::vector<Accelerogram> levels = floorMotions(model, ground, {0.02, std::nullopt});
    const Accelerogram sdof = floorMotion(ground, {1.0, 0.02, std::nullopt});
    QCOMPARE(levels.size(), std::size_t(1));
    QCOMPARE(levels[0].size(), sdof.size());
    for (std::size_t k = 0; k < sdof.size(); ++k)
        QCOMPARE_LT(std::abs(levels[0].samples[k] - sdof.samples[k]), 1e-12);
}

void TestFloorsModel::matchesRk4OfTheFullSystem() {
    const Accelerogram ground = pacoima(4.0);
    const double zeta = 0.05;
    const ShearBuilding s =
        shearBuilding(building(4, 0.6, {1.2, 1.0, 1.0, 0.7}), StiffnessProfile::Weight);
    const ModalModel model = modalModel(s);
    const std::vector<Accelerogram> levels = floorMotions(model, ground, {zeta, 0.0});
    // C = sum_r (2 zeta w_r / M_r) (M phi_r)(M phi_r)': the damping matrix whose modes are
    // those of K with ratio zeta in every mode (Chopra, "Dynamics of Structures", §11.4).
    const Eigen::MatrixXd M = massMatrix(s), K = stiffnessMatrix(s);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(4, 4);
    for (const Mode& m : model.modes) {
        const Eigen::Map<const Eigen::VectorXd> phi(m.shape.data(), 4);
        const Eigen::VectorXd mp = M * phi;
        C += 2 * zeta * m.omega / phi.dot(mp) * mp * mp.transpose();
    }
    const Eigen::MatrixXd Minv = M.inverse();
    const auto ag = [&](double t) {
        const double x = t / ground.dt;
        const auto k = std::min(static_cast<std::size_t>(x), ground.size() - 2);
        return ground.samples[k] + (x - double(k)) * (ground.samples[k + 1] - ground.samples[k]);
    };
    // State y = (u, u'), u relative to the ground; u'' = -M^-1 (C u' + K u) - a_g.
    const auto f = [&](double t, const Eigen::VectorXd& y) {
        Eigen::VectorXd d(8);
        d.head(4) = y.tail(4);
        d.tail(4) = -Minv * (C * y.tail(4) + K * y.head(4)) - Eigen::VectorXd::Constant(4, ag(t));
        return d;
    };
    const int sub = 200;
    const double h = ground.dt / sub;
    Eigen::VectorXd y = Eigen::VectorXd::Zero(8);
    double peak = 0, worst = 0;
    for (std::size_t k = 0; k + 1 < ground.size(); ++k) {
        for (int j = 0; j < sub; ++j) {
            const double t = ground.dt * double(k) + h * j;
            const Eigen::VectorXd k1 = f(t, y), k2 = f(t + h / 2, y + h / 2 * k1),
                                  k3 = f(t + h / 2, y + h / 2 * k2), k4 = f(t + h, y + h * k3);
            y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        const Eigen::VectorXd absolute = -Minv * (C * y.tail(4) + K * y.head(4));
        for (int i = 0; i < 4; ++i) {
            peak = std::max(peak, std::abs(absolute(i)));
            worst = std::max(worst, std::abs(absolute(i) - levels[i].samples[k + 1]));
        }
    }
    qInfo("RK4 of the MDOF system: largest difference %.3g g on a peak of %.4g g", worst, peak);
    QVERIFY(peak > 0.1);
    QVERIFY2(worst < 1e-6 * peak, qPrintable(QString("worst %1 of peak %2").arg(worst).arg(peak)));
}

void TestFloorsModel::roofOfThePaperBuildingAgainstTheFloorFilter() {
    // The paper's building (16 levels, 177 ft, T = 1 s) under Pacoima Dam 164: the roof of the
    // shear building and the paper's SDOF floor filter share the first mode, so their peaks are
    // of the same order; the higher modes make the roof motion differ from the filter's.
    const Accelerogram ground = readRecord(kRecords + "RSN77_SFERN_PUL164.AT2");
    Building b = building(16, 1.0);
    b.height = 177.0;
    const ModalModel model = modalModel(shearBuilding(b, StiffnessProfile::Uniform));
    const auto levels = floorMotions(model, ground, {0.05, std::nullopt});
    const double roof = std::abs(levels.back().peak().value);
    const double sdof = std::abs(floorMotion(ground, {1.0, 0.05, std::nullopt}).peak().value);
    // Gamma_1 phi_roof,1 of a uniform 16-storey shear building is about 1.27: the first mode
    // alone scales the SDOF motion by that; other modes add or subtract.
    QCOMPARE_LT(std::abs(model.modes[0].participation - 1.27), 0.01);
    QVERIFY(roof > 0.5 * sdof && roof < 3.0 * sdof);
    QCOMPARE_GT(std::abs(roof - sdof), 0.01); // not the same motion
}

QTEST_APPLESS_MAIN(TestFloorsModel)
#include "tst_floors_model.moc"
