// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/InputLabels.h"

#include "core/codes/Asce7_22.h"
#include "core/codes/Atc306.h"
#include "core/codes/CodeCatalog.h"
#include "core/codes/Eurocode8.h"
#include "core/codes/Ubc1976.h"
#include "core/codes/Ubc1997.h"
#include "report/ReportSections.h"

namespace kinstab::report {

QString systemLabel(StructuralSystem s) {
    switch (s) {
    case StructuralSystem::SteelMomentFrame:
        return QStringLiteral("steel moment frame");
    case StructuralSystem::ConcreteMomentFrame:
        return QStringLiteral("reinforced-concrete moment frame");
    case StructuralSystem::SteelBracedEccentric:
        return QStringLiteral("steel eccentrically braced frame");
    case StructuralSystem::DualFrameWall:
        return QStringLiteral("dual system: moment frame with shear walls");
    case StructuralSystem::ShearWall:
        return QStringLiteral("shear walls (concrete or masonry)");
    case StructuralSystem::BracedFrame:
        return QStringLiteral("concentrically braced frame");
    case StructuralSystem::Other:
        return QStringLiteral("other");
    }
    return {};
}

QString occupancyLabel(Occupancy o) {
    switch (o) {
    case Occupancy::Standard:
        return QStringLiteral("standard (offices, dwellings, commerce)");
    case Occupancy::Assembly:
        return QStringLiteral("assembly (more than 300 persons in one room)");
    case Occupancy::Hazardous:
        return QStringLiteral("hazardous contents");
    case Occupancy::Essential:
        return QStringLiteral("essential facility (hospital, fire station)");
    }
    return {};
}

namespace {

class Rows {
public:
    Rows(Table& t, CodeKey code) : t_(t), code_(QString::fromUtf8(codeInfo(code).shortName)) {}
    void add(const QString& input, const QString& symbol, const QString& value,
             const QString& unit = {}) {
        t_.rows.push_back({first_ ? code_ : QString(), input, symbol, value, unit});
        first_ = false;
    }
    void add(const QString& input, const QString& symbol, const std::optional<double>& v,
             const QString& open, const QString& unit = {}) {
        add(input, symbol, v ? coefficient(*v) : open, v ? unit : QString());
    }

private:
    Table& t_;
    QString code_;
    bool first_ = true;
};

void ubc1976Rows(Table& t, const Ubc1976Inputs& in) {
    Rows r(t, CodeKey::Ubc1976);
    r.add(QStringLiteral("seismic zone"), QStringLiteral("Z"), QString::number(in.zone));
    r.add(QStringLiteral("horizontal force factor"), QStringLiteral("K"), coefficient(in.k));
    r.add(QStringLiteral("occupancy importance factor"), QStringLiteral("I"), in.importance,
          QStringLiteral("from the occupancy"));
    r.add(QStringLiteral("site period"), QStringLiteral("T_s"), in.sitePeriod,
          QStringLiteral("not established (S = 1.5)"), QStringLiteral("s"));
}

void atcRows(Table& t, const Atc306Inputs& in) {
    Rows r(t, CodeKey::Atc306);
    if (in.mapArea) r.add(QStringLiteral("map area"), QString(), QString::number(*in.mapArea));
    r.add(QStringLiteral("effective peak acceleration"), QStringLiteral("A_a"), coefficient(in.aa),
          QStringLiteral("g"));
    r.add(QStringLiteral("effective peak velocity-related acceleration"), QStringLiteral("A_v"),
          coefficient(in.av), QStringLiteral("g"));
    r.add(QStringLiteral("soil profile"), QString(), qs(atcSoilName(in.soil)));
    r.add(QStringLiteral("response modification factor"), QStringLiteral("R"), coefficient(in.r));
}

void ubc1997Rows(Table& t, const Ubc1997Inputs& in) {
    Rows r(t, CodeKey::Ubc1997);
    r.add(QStringLiteral("seismic zone"), QString(), qs(ubc97ZoneName(in.zone)));
    r.add(QStringLiteral("soil profile type"), QString(), qs(ubc97SoilName(in.soil)));
    r.add(QStringLiteral("near-source factors"), QStringLiteral("N_a, N_v"),
          coefficient(in.na) + ", " + coefficient(in.nv));
    r.add(QStringLiteral("importance factor"), QStringLiteral("I"), in.importance,
          QStringLiteral("from the occupancy"));
    r.add(QStringLiteral("response modification factor"), QStringLiteral("R"), coefficient(in.r));
}

void asceRows(Table& t, const Asce7Inputs& in) {
    Rows r(t, CodeKey::Asce7_22);
    r.add(QStringLiteral("design spectral acceleration, short periods"), QStringLiteral("S_DS"),
          coefficient(in.sds), QStringLiteral("g"));
    r.add(QStringLiteral("design spectral acceleration, 1 s"), QStringLiteral("S_D1"),
          coefficient(in.sd1), QStringLiteral("g"));
    r.add(QStringLiteral("MCE_R spectral acceleration, 1 s"), QStringLiteral("S_1"), in.s1,
          QStringLiteral("not given (eq. 12.8-6 not checked)"), QStringLiteral("g"));
    r.add(QStringLiteral("long-period transition period"), QStringLiteral("T_L"),
          coefficient(in.tl), QStringLiteral("s"));
    r.add(QStringLiteral("site class"), QString(), qs(in.siteClass));
    r.add(QStringLiteral("risk category"), QString(),
          in.riskCategory ? QString::number(*in.riskCategory)
                          : QStringLiteral("from the occupancy"));
    r.add(QStringLiteral("importance factor"), QStringLiteral("I_e"), in.importance,
          QStringLiteral("from the risk category"));
    r.add(QStringLiteral("response modification coefficient"), QStringLiteral("R"),
          coefficient(in.r));
}

void ec8Rows(Table& t, const Eurocode8Inputs& in) {
    Rows r(t, CodeKey::Ec8);
    r.add(QStringLiteral("ground type"), QString(), qs(ec8GroundName(in.ground)));
    r.add(QStringLiteral("elastic spectrum type"), QString(), QString::number(in.spectrumType));
    r.add(QStringLiteral("reference peak ground acceleration"), QStringLiteral("a_gR"),
          coefficient(in.agr), QStringLiteral("g"));
    r.add(QStringLiteral("importance class"), QString(),
          in.importanceClass ? QString::number(*in.importanceClass)
                             : QStringLiteral("from the occupancy"));
    r.add(QStringLiteral("importance factor"), QStringLiteral("γ_I"), in.gammaI,
          QStringLiteral("recommended value of the class"));
    r.add(QStringLiteral("behaviour factor"), QStringLiteral("q"), coefficient(in.q));
    r.add(QStringLiteral("lower-bound factor"), QStringLiteral("β"), coefficient(in.beta));
    r.add(QStringLiteral("regular in elevation"), QString(),
          in.regularInElevation ? QStringLiteral("yes") : QStringLiteral("no"));
}

} // namespace

Table codeInputsTable(const CodeSelection& codes) {
    Table t{{"code", "input", "symbol", "value", "unit"},
            {},
            {1.1, 3.1, 0.8, 2.5, 0.5},
            {Align::Left, Align::Left, Align::Left, Align::Right, Align::Left},
            {}};
    if (codes.ubc1976) ubc1976Rows(t, *codes.ubc1976);
    if (codes.atc306) atcRows(t, *codes.atc306);
    if (codes.ubc1997) ubc1997Rows(t, *codes.ubc1997);
    if (codes.asce7_22) asceRows(t, *codes.asce7_22);
    if (codes.ec8) ec8Rows(t, *codes.ec8);
    return t;
}

} // namespace kinstab::report
