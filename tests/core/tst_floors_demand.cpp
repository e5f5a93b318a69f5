// SPDX-License-Identifier: GPL-3.0-or-later
// The codes' floor-acceleration demands:
//  - ASCE 7-22 eq. 13.3-4 (H_f) at the worked values T_a = 1.0 s (a_1 = 1, a_2 = 0.84,
//    H_f(roof) = 2.84) and T_a = 0.4 s (a_1 = 2.5, a_2 = 0, H_f(roof) = 3.5), evaluated by hand
//    from the equation; eq. 13.3-6 (R_mu) with its 1.3 floor;
//  - the paper's building (177 ft, dual system: T_a = 0.02 x 177^0.75 = 0.9705 s, Table 12.8-2)
//    with S_DS = 1.0, R = 6, I_e = 1, Omega_0 = 2.5: hand values of H_f, R_mu and the PFA;
//  - EN 1998-1 eq. 4.25: a rigid element at the roof 2.5 alpha S, at the base alpha S; an element
//    tuned to the building (T_a = T_1) at the roof 5.5 alpha S; the alpha S floor;
//  - the verdict of a demand against a critical floor peak.

#include "core/codes/Asce7FloorDemand.h"
#include "core/codes/Ec8FloorDemand.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

namespace {
Building paperBuilding() {
    Building b; // defaults: 16 stories, 177 ft, dual frame-wall, standard occupancy
    b.period = 1.0;
    return b;
}
bool near(double a, double b, double tol) {
    return std::abs(a - b) <= tol;
}
} // namespace

class TestFloorsDemand : public QObject {
    Q_OBJECT
private slots:
    void heightFactorWorkedValues();
    void ductilityFactor();
    void asce7PaperBuilding();
    void ec8Factor();
    void ec8PaperBuilding();
    void groundLevelAndBadInput();
};

void TestFloorsDemand::heightFactorWorkedValues() {
    QVERIFY(near(asce7HeightFactor(1.0, 1.0), 2.84, 1e-12));
    QVERIFY(near(asce7HeightFactor(1.0, 0.4), 3.5, 1e-12));
    QVERIFY(near(asce7HeightFactor(0.0, 0.7), 1.0, 1e-15)); // at the base
    // T_a = 0.2 s: a_1 capped at 2.5, a_2 = 1 - 4 < 0 set to 0.
    QVERIFY(near(asce7HeightFactor(0.5, 0.2), 1.0 + 2.5 * 0.5, 1e-12));
    // Mid-height of a 1 s building: 1 + 0.5 + 0.84 x 0.5^10.
    QVERIFY(near(asce7HeightFactor(0.5, 1.0), 1.5 + 0.84 / 1024.0, 1e-12));
}

void TestFloorsDemand::ductilityFactor() {
    QVERIFY(near(asce7DuctilityFactor(8.0, 1.0, 3.0), std::sqrt(8.8 / 3.0), 1e-12));
    QCOMPARE(asce7DuctilityFactor(3.0, 1.5, 3.0), 1.3); // sqrt(3.3/4.5) = 0.86 < 1.3
}

void TestFloorsDemand::asce7PaperBuilding() {
    const Building b = paperBuilding();
    const FloorDemand d = asce7FloorDemand(b, Asce7Inputs{}, 2.5, 16, false);
    const FloorDemand mce = asce7FloorDemand(b, Asce7Inputs{}, 2.5, 16, true);
    // Hand: 177^0.75 = exp(0.75 ln 177) = 48.527; T_a = 0.97053 s; H_f(roof) = 1 + 1/0.97053
    // + 1 - (0.4/0.97053)^2 = 2.86050; R_mu = sqrt(1.1 x 6 / 2.5) = 1.62481;
    // PFA = 0.4 x 1.0 x 2.86050 / 1.62481 = 0.70421 g; MCE_R: x 1.5 = 1.05631 g.
    QVERIFY(near(d.trail.front().value, 0.97053, 5e-5));
    QVERIFY(near(d.factor.back(), 2.86050, 5e-5));
    QVERIFY(near(d.slabPfa, 0.70421, 5e-5));
    QVERIFY(near(mce.slabPfa, 1.05631, 5e-5));
    QCOMPARE(d.pfa.size(), std::size_t(16));
    for (std::size_t i = 1; i < 16; ++i)
        QVERIFY(d.pfa[i] > d.pfa[i - 1]); // grows with height
    // Level 8 of 16 equal storeys: z/h = 0.5.
    const FloorDemand mid = asce7FloorDemand(b, Asce7Inputs{}, 2.5, 8, false);
    QVERIFY(near(mid.trail[3].value, 0.5, 1e-15));
    QCOMPARE(mid.slabPfa, d.pfa[7]);
}

void TestFloorsDemand::ec8Factor() {
    QCOMPARE(ec8FloorFactor(1.0, 0.0, 1.0), 2.5); // rigid, roof: 3 x 2 / 2 - 0.5
    QCOMPARE(ec8FloorFactor(0.0, 0.0, 1.0), 1.0); // rigid, base
    QCOMPARE(ec8FloorFactor(1.0, 1.0, 1.0), 5.5); // resonant, roof: 3 x 2 / 1 - 0.5
    QCOMPARE(ec8FloorFactor(0.0, 3.0, 1.0), 1.0); // 3/5 - 0.5 = 0.1 < 1: the alpha S floor
    QVERIFY(near(ec8FloorFactor(0.5, 0.0, 1.0), 1.75, 1e-15)); // 1 + 1.5 z/H
}

void TestFloorsDemand::ec8PaperBuilding() {
    // Ground C (S = 1.15, Table 3.2), a_gR = 0.25 g, class II (gamma_I = 1): roof, rigid:
    // 0.25 x 1.15 x 2.5 = 0.71875 g.
    const FloorDemand d = ec8FloorDemand(paperBuilding(), Eurocode8Inputs{}, std::nullopt, 16);
    QVERIFY(near(d.slabPfa, 0.71875, 1e-12));
    QVERIFY(near(d.pfa.front(), 0.2875 * (1.0 + 1.5 / 16.0), 1e-12));
    const FloorDemand tuned = ec8FloorDemand(paperBuilding(), Eurocode8Inputs{}, 1.0, 16);
    QVERIFY(near(tuned.slabPfa, 0.2875 * 5.5, 1e-12));
}

void TestFloorsDemand::groundLevelAndBadInput() {
    // The ground acceleration each code level implies, the same expressions at grade: ASCE 7-22
    // 0.4 S_DS (H_f = 1, R_mu = 1 at grade, §13.3.1.1) and 0.4 S_MS = 0.6 S_DS; EN 1998-1
    // alpha S = 0.25 x 1.15 (the factor of eq. 4.25 is 1 at z = 0 for a rigid element).
    const Asce7Inputs asce;
    const FloorDemand design = asce7FloorDemand(paperBuilding(), asce, 2.5, 16, false);
    const FloorDemand mce = asce7FloorDemand(paperBuilding(), asce, 2.5, 16, true);
    QVERIFY(near(design.groundPga, 0.4 * asce.sds, 1e-15));
    QVERIFY(near(mce.groundPga, 0.6 * asce.sds, 1e-15));
    QCOMPARE(mce.groundPgaSource, std::string("0.4 S_MS"));
    const FloorDemand ec8 = ec8FloorDemand(paperBuilding(), Eurocode8Inputs{}, std::nullopt, 16);
    QVERIFY(near(ec8.groundPga, 0.2875, 1e-15));
    QVERIFY(near(ec8.groundPga, ec8.pfa.front() / ec8.factor.front(), 1e-15));
    QVERIFY_THROWS_EXCEPTION(InputError,
                             asce7FloorDemand(paperBuilding(), Asce7Inputs{}, 2.5, 17, false));
    try {
        ec8FloorDemand(paperBuilding(), Eurocode8Inputs{}, -1.0, 16);
        QFAIL("a negative element period was accepted");
    } catch (const InputError& e) {
        QVERIFY(QString(e.what()).contains("floors.ec8_element_period_s = -1"));
    }
}

QTEST_APPLESS_MAIN(TestFloorsDemand)
#include "tst_floors_demand.moc"
