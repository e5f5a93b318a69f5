// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/CodesPanel.h"

#include "ui/NumberField.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>

namespace kinstab::ui {

namespace {
const QStringList romans = {QStringLiteral("I"), QStringLiteral("II"), QStringLiteral("III"),
                            QStringLiteral("IV")};
QString fromOccupancy() {
    return CodesPanel::tr("from the occupancy");
}
} // namespace

CodesPanel::CodesPanel(QWidget* parent) : InputPanel(parent) {
    buildUbc1976();
    buildAtc306();
    buildUbc1997();
    buildAsce7();
    buildEc8();
    CodeSelection defaults;
    defaults.ubc1976 = Ubc1976Inputs{};
    defaults.atc306 = Atc306Inputs{};
    setCodes(defaults);
}

// The group's title is the code's entry in the catalogue (core/codes/CodeCatalog.h).
QGroupBox* CodesPanel::group(CodeKey code, const QString& toolTip) {
    const std::string_view title = codeInfo(code).title;
    auto* g = new QGroupBox(QString::fromUtf8(title.data(), qsizetype(title.size())), this);
    g->setCheckable(true);
    g->setToolTip(toolTip);
    auto* f = new QFormLayout(g);
    f->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    form()->addRow(g);
    connect(g, &QGroupBox::toggled, this, &InputPanel::changed);
    return g;
}

NumberField* CodesPanel::field(QFormLayout* f, const char* name, const QString& label,
                               const QString& unit, const QString& toolTip) {
    auto* n = new NumberField(unit, this);
    n->setObjectName(QString::fromLatin1(name));
    n->setFieldToolTip(toolTip);
    f->addRow(label, n);
    track(n, label);
    return n;
}

QComboBox* CodesPanel::combo(QFormLayout* f, const QString& label, const QStringList& items,
                             const QString& toolTip) {
    auto* c = new QComboBox(this);
    c->addItems(items);
    c->setToolTip(toolTip);
    f->addRow(label, c);
    connect(c, &QComboBox::currentIndexChanged, this, &InputPanel::changed);
    return c;
}

void CodesPanel::buildUbc1976() {
    m_ubc76 =
        group(CodeKey::Ubc1976, tr("Uniform Building Code 1976: V = Z I K C S W, top force F_t."));
    auto* f = static_cast<QFormLayout*>(m_ubc76->layout());
    m_ubc76Zone =
        combo(f, tr("Zone:"), {"0", "1", "2", "3", "4"},
              tr("Seismic zone of the UBC map (Figure 1): Z = 0, 3/16, 3/8, 3/4, 1. Zone 4 "
                 "is the San Andreas region."));
    m_ubc76K =
        field(f, "ubc76K", tr("K:"), QString(),
              tr("Horizontal force factor (Table 23-I): 0.67 ductile frame, 0.80 dual system "
                 "(the paper), 1.00 other, 1.33 box system."));
    m_ubc76K->setCheck(rangeCheck(kUbc1976K));
    m_ubc76I =
        field(f, "ubc76I", tr("I:"), QString(),
              tr("Occupancy importance factor (Table 23-K): 1.5 essential, 1.25 assembly, 1.0 "
                 "otherwise. Leave empty to take it from the occupancy."));
    m_ubc76I->setOptional(fromOccupancy());
    m_ubc76I->setCheck(rangeCheck(kUbc1976Importance));
    m_ubc76Ts =
        field(f, "ubc76Ts", tr("Site period T_s:"), tr("s"),
              tr("Characteristic site period for the resonance coefficient S. Leave empty when "
                 "not established: S = 1.5."));
    m_ubc76Ts->setOptional(tr("not established (S = 1.5)"));
    m_ubc76Ts->setCheck(rangeCheck(kUbc1976SitePeriod));
}

void CodesPanel::buildAtc306() {
    m_atc = group(CodeKey::Atc306,
                  tr("Tentative Provisions: C_s = 1.2 A_v S / (R T^(2/3)) ≤ 2.5 A_a / R."));
    auto* f = static_cast<QFormLayout*>(m_atc->layout());
    m_atcArea = combo(f, tr("Map area:"), {tr("enter A_a, A_v"), "1", "2", "3", "4", "5", "6", "7"},
                      tr("Map area of Table 1-B; A_a = A_v follow from it. Area 7 ≈ UBC zone 4."));
    m_atcAa =
        field(f, "atcAa", tr("A_a:"), tr("g"), tr("Effective peak acceleration coefficient."));
    m_atcAv = field(f, "atcAv", tr("A_v:"), tr("g"),
                    tr("Effective peak velocity-related acceleration coefficient."));
    for (NumberField* n : {m_atcAa, m_atcAv})
        n->setCheck(rangeCheck(kAtc306Acceleration));
    m_atcSoil =
        combo(f, tr("Soil:"),
              {tr("S1 rock / stiff < 200 ft"), tr("S2 deep stiff"), tr("S3 soft clay ≥ 30 ft")},
              tr("Soil profile (Table 3-A): S = 1.0, 1.2, 1.5. The paper's site has S3."));
    m_atcR =
        field(f, "atcR", tr("R:"), QString(),
              tr("Response modification factor (Table 3-B); 5.5 for the paper's dual system."));
    m_atcR->setCheck(rangeCheck(kAtc306R));
    connect(m_atcArea, &QComboBox::currentIndexChanged, this, [this](int i) {
        m_atcAa->setEnabled(i == 0);
        m_atcAv->setEnabled(i == 0);
    });
}

void CodesPanel::buildUbc1997() {
    m_ubc97 = group(CodeKey::Ubc1997,
                    tr("Strength-level UBC: V = C_v I W / (R T), capped at 2.5 C_a I W / R."));
    auto* f = static_cast<QFormLayout*>(m_ubc97->layout());
    m_ubc97Zone = combo(f, tr("Zone:"), {"1", "2A", "2B", "3", "4"},
                        tr("Seismic zone (Table 16-I): Z = 0.075 … 0.40."));
    m_ubc97Soil = combo(f, tr("Soil:"), {"S_A", "S_B", "S_C", "S_D", "S_E"},
                        tr("Soil profile type (Table 16-J); S_D when unknown."));
    m_ubc97Na =
        field(f, "ubc97Na", tr("N_a:"), QString(), tr("Near-source factor on C_a (zone 4)."));
    m_ubc97Nv =
        field(f, "ubc97Nv", tr("N_v:"), QString(), tr("Near-source factor on C_v (zone 4)."));
    m_ubc97Na->setCheck(rangeCheck(kUbc1997Na));
    m_ubc97Nv->setCheck(rangeCheck(kUbc1997Nv));
    m_ubc97I = field(f, "ubc97I", tr("I:"), QString(), tr("Importance factor (Table 16-K)."));
    m_ubc97I->setOptional(fromOccupancy());
    m_ubc97I->setCheck(rangeCheck(kUbc1997Importance));
    m_ubc97R =
        field(f, "ubc97R", tr("R:"), QString(), tr("Response modification factor (Table 16-N)."));
    m_ubc97R->setCheck(rangeCheck(kUbc1997R));
}

void CodesPanel::buildAsce7() {
    m_asce = group(CodeKey::Asce7_22,
                   tr("Equivalent lateral force: C_s = S_DS / (R / I_e), limited by S_D1."));
    auto* f = static_cast<QFormLayout*>(m_asce->layout());
    m_asceSds = field(f, "asceSds", tr("S_DS:"), tr("g"),
                      tr("Design spectral acceleration at short periods (USGS service)."));
    m_asceSd1 =
        field(f, "asceSd1", tr("S_D1:"), tr("g"), tr("Design spectral acceleration at 1 s."));
    for (NumberField* n : {m_asceSds, m_asceSd1})
        n->setCheck(rangeCheck(kAsce7Sd));
    m_asceS1 = field(f, "asceS1", tr("S_1:"), tr("g"),
                     tr("MCE_R acceleration at 1 s; only for the 0.5 S_1 floor."));
    m_asceS1->setOptional(tr("not given"));
    m_asceS1->setCheck(rangeCheck(kAsce7S1));
    m_asceTl = field(f, "asceTl", tr("T_L:"), tr("s"),
                     tr("Long-period transition period (Fig. 22-14 … 22-17)."));
    m_asceTl->setCheck(rangeCheck(kAsce7Tl));
    m_asceSite =
        combo(f, tr("Site class:"), {"A", "B", "BC", "C", "CD", "D", "DE", "E", "F", "Default"},
              tr("Site class (§20.3); S_DS and S_D1 already include it."));
    m_asceRisk = combo(f, tr("Risk category:"), QStringList{fromOccupancy()} + romans,
                       tr("Risk category (Table 1.5-1)."));
    m_asceI =
        field(f, "asceI", tr("I_e:"), QString(), tr("Seismic importance factor (Table 1.5-2)."));
    m_asceI->setOptional(tr("from the risk category"));
    m_asceI->setCheck(rangeCheck(kAsce7Importance));
    m_asceR = field(f, "asceR", tr("R:"), QString(),
                    tr("Response modification coefficient (Table 12.2-1)."));
    m_asceR->setCheck(rangeCheck(kAsce7R));
}

void CodesPanel::buildEc8() {
    m_ec8 = group(CodeKey::Ec8, tr("Lateral force method: F_b = S_d(T_1) m λ."));
    auto* f = static_cast<QFormLayout*>(m_ec8->layout());
    m_ec8Ground =
        combo(f, tr("Ground type:"), {"A", "B", "C", "D", "E"}, tr("Ground type (Table 3.1)."));
    m_ec8Type = combo(f, tr("Spectrum:"), {tr("Type 1 (M_s > 5.5)"), tr("Type 2 (M_s ≤ 5.5)")},
                      tr("Elastic spectrum type (§3.2.2.2)."));
    m_ec8Agr = field(f, "ec8Agr", tr("a_gR:"), tr("g"),
                     tr("Reference peak ground acceleration on ground type A."));
    m_ec8Agr->setCheck(rangeCheck(kEc8Agr));
    m_ec8Class = combo(f, tr("Importance class:"), QStringList{fromOccupancy()} + romans,
                       tr("Importance class (Table 4.3)."));
    m_ec8GammaI = field(f, "ec8GammaI", tr("γ_I:"), QString(),
                        tr("Importance factor; empty: the class's recommended value."));
    m_ec8GammaI->setOptional(tr("recommended for the class"));
    m_ec8GammaI->setCheck(rangeCheck(kEc8GammaI));
    m_ec8Q = field(f, "ec8Q", tr("q:"), QString(),
                   tr("Behaviour factor (§5.2.2.2); 3.9 for a DCM frame or dual system."));
    m_ec8Q->setCheck(rangeCheck(kEc8Q));
    m_ec8Beta = field(f, "ec8Beta", tr("β:"), QString(),
                      tr("Lower-bound factor of the design spectrum (0.2 recommended)."));
    m_ec8Beta->setCheck(rangeCheck(kEc8Beta));
    m_ec8Regular = new QCheckBox(tr("Regular in elevation"), this);
    m_ec8Regular->setToolTip(tr("The lateral force method requires it (§4.3.3.2.1)."));
    f->addRow(QString(), m_ec8Regular);
    connect(m_ec8Regular, &QCheckBox::toggled, this, &InputPanel::changed);
}

namespace {
// A combo whose first item means "none" (no map area, from the occupancy).
std::optional<int> optionalIndex(const QComboBox* c) {
    return c->currentIndex() == 0 ? std::nullopt : std::optional<int>(c->currentIndex());
}
} // namespace

Ubc1976Inputs CodesPanel::ubc1976Inputs() const {
    Ubc1976Inputs in = m_kept.ubc1976.value_or(Ubc1976Inputs{});
    in.zone = m_ubc76Zone->currentIndex();
    in.k = m_ubc76K->value().value_or(in.k);
    in.importance = m_ubc76I->value();
    in.sitePeriod = m_ubc76Ts->value();
    return in;
}

Atc306Inputs CodesPanel::atc306Inputs() const {
    Atc306Inputs in = m_kept.atc306.value_or(Atc306Inputs{});
    in.mapArea = optionalIndex(m_atcArea);
    in.aa = m_atcAa->value().value_or(in.aa);
    in.av = m_atcAv->value().value_or(in.av);
    in.soil = static_cast<AtcSoil>(m_atcSoil->currentIndex());
    in.r = m_atcR->value().value_or(in.r);
    return in;
}

Ubc1997Inputs CodesPanel::ubc1997Inputs() const {
    Ubc1997Inputs in = m_kept.ubc1997.value_or(Ubc1997Inputs{});
    in.zone = static_cast<Ubc97Zone>(m_ubc97Zone->currentIndex());
    in.soil = static_cast<Ubc97Soil>(m_ubc97Soil->currentIndex());
    in.na = m_ubc97Na->value().value_or(in.na);
    in.nv = m_ubc97Nv->value().value_or(in.nv);
    in.importance = m_ubc97I->value();
    in.r = m_ubc97R->value().value_or(in.r);
    return in;
}

Asce7Inputs CodesPanel::asce7Inputs() const {
    Asce7Inputs in = m_kept.asce7_22.value_or(Asce7Inputs{});
    in.sds = m_asceSds->value().value_or(in.sds);
    in.sd1 = m_asceSd1->value().value_or(in.sd1);
    in.s1 = m_asceS1->value();
    in.tl = m_asceTl->value().value_or(in.tl);
    in.siteClass = m_asceSite->currentText().toStdString();
    in.riskCategory = optionalIndex(m_asceRisk);
    in.importance = m_asceI->value();
    in.r = m_asceR->value().value_or(in.r);
    return in;
}

Eurocode8Inputs CodesPanel::ec8Inputs() const {
    Eurocode8Inputs in = m_kept.ec8.value_or(Eurocode8Inputs{});
    in.ground = static_cast<Ec8Ground>(m_ec8Ground->currentIndex());
    in.spectrumType = m_ec8Type->currentIndex() + 1;
    in.agr = m_ec8Agr->value().value_or(in.agr);
    in.importanceClass = optionalIndex(m_ec8Class);
    in.gammaI = m_ec8GammaI->value();
    in.q = m_ec8Q->value().value_or(in.q);
    in.beta = m_ec8Beta->value().value_or(in.beta);
    in.regularInElevation = m_ec8Regular->isChecked();
    return in;
}

CodeSelection CodesPanel::codes() const {
    CodeSelection c;
    if (m_ubc76->isChecked()) c.ubc1976 = ubc1976Inputs();
    if (m_atc->isChecked()) c.atc306 = atc306Inputs();
    if (m_ubc97->isChecked()) c.ubc1997 = ubc1997Inputs();
    if (m_asce->isChecked()) c.asce7_22 = asce7Inputs();
    if (m_ec8->isChecked()) c.ec8 = ec8Inputs();
    return c;
}

void CodesPanel::setCodes(const CodeSelection& c) {
    m_kept = c;
    const Ubc1976Inputs u76 = c.ubc1976.value_or(Ubc1976Inputs{});
    m_ubc76->setChecked(c.ubc1976.has_value());
    m_ubc76Zone->setCurrentIndex(u76.zone);
    m_ubc76K->setValue(u76.k);
    m_ubc76I->setOptionalValue(u76.importance);
    m_ubc76Ts->setOptionalValue(u76.sitePeriod);

    const Atc306Inputs atc = c.atc306.value_or(Atc306Inputs{});
    m_atc->setChecked(c.atc306.has_value());
    m_atcArea->setCurrentIndex(atc.mapArea.value_or(0));
    m_atcAa->setValue(atc.aa);
    m_atcAv->setValue(atc.av);
    m_atcSoil->setCurrentIndex(static_cast<int>(atc.soil));
    m_atcR->setValue(atc.r);

    const Ubc1997Inputs u97 = c.ubc1997.value_or(Ubc1997Inputs{});
    m_ubc97->setChecked(c.ubc1997.has_value());
    m_ubc97Zone->setCurrentIndex(static_cast<int>(u97.zone));
    m_ubc97Soil->setCurrentIndex(static_cast<int>(u97.soil));
    m_ubc97Na->setValue(u97.na);
    m_ubc97Nv->setValue(u97.nv);
    m_ubc97I->setOptionalValue(u97.importance);
    m_ubc97R->setValue(u97.r);

    const Asce7Inputs asce = c.asce7_22.value_or(Asce7Inputs{});
    m_asce->setChecked(c.asce7_22.has_value());
    m_asceSds->setValue(asce.sds);
    m_asceSd1->setValue(asce.sd1);
    m_asceS1->setOptionalValue(asce.s1);
    m_asceTl->setValue(asce.tl);
    m_asceSite->setCurrentText(QString::fromStdString(asce.siteClass));
    m_asceRisk->setCurrentIndex(asce.riskCategory.value_or(0));
    m_asceI->setOptionalValue(asce.importance);
    m_asceR->setValue(asce.r);

    const Eurocode8Inputs ec8 = c.ec8.value_or(Eurocode8Inputs{});
    m_ec8->setChecked(c.ec8.has_value());
    m_ec8Ground->setCurrentIndex(static_cast<int>(ec8.ground));
    m_ec8Type->setCurrentIndex(ec8.spectrumType - 1);
    m_ec8Agr->setValue(ec8.agr);
    m_ec8Class->setCurrentIndex(ec8.importanceClass.value_or(0));
    m_ec8GammaI->setOptionalValue(ec8.gammaI);
    m_ec8Q->setValue(ec8.q);
    m_ec8Beta->setValue(ec8.beta);
    m_ec8Regular->setChecked(ec8.regularInElevation);
}

} // namespace kinstab::ui
