// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/FrictionCalibration.h"

#include <algorithm>
#include <functional>

namespace kinstab {
namespace {

GroupCalibration calibrateGroup(const std::vector<TripletCurve>& runs,
                                const CalibrationOptions& o) {
    GroupCalibration g;
    g.configuration = runs.front().configuration;
    g.cpPsi = runs.front().cpPsi;
    std::vector<double> vInf;
    for (const TripletCurve& c : runs) {
        g.runs.push_back({c, fitDecayBestBeta(c, o.betas, o.fit), false});
        vInf.push_back(g.runs.back().fit.vInf);
    }
    const bool spread =
        std::adjacent_find(vInf.begin(), vInf.end(), std::not_equal_to<>()) != vInf.end();
    if (static_cast<int>(runs.size()) >= std::max(o.outlierMinRuns, 3) && spread) {
        g.outlier = grubbsTest(vInf, o.outlierAlpha, o.outlierSide);
        if (o.excludeOutliers && g.outlier->rejected) g.runs[g.outlier->index].excluded = true;
    }
    std::vector<TripletCurve> kept;
    std::vector<double> keptVInf;
    for (const RunFit& r : g.runs)
        if (!r.excluded) kept.push_back(r.curve), keptVInf.push_back(r.fit.vInf);
    if (keptVInf.size() >= 3)
        for (double tail : o.intervalTails)
            g.intervals.push_back(sampleIntervals(keptVInf, tail));
    g.composite = compositeCurve(kept);
    g.fit = fitDecayBestBeta(g.composite, o.betas, o.fit);
    return g;
}

ConfigurationCalibration calibrateConfiguration(const std::string& name,
                                                const std::vector<GroupCalibration>& groups,
                                                const CalibrationOptions& o) {
    ConfigurationCalibration c;
    c.configuration = name;
    for (const GroupCalibration& g : groups)
        if (g.configuration == name) c.points.push_back({g.cpPsi, g.fit.vInf});
    try {
        c.coulomb = fitCoulombSlope(c.points, o.maxCpPsi, o.bearingAreaIn2);
    } catch (const std::invalid_argument& e) {
        c.coulombError = e.what();
    }
    return c;
}

} // namespace

std::vector<TripletCurve> runsOf(const std::vector<TripletCurve>& runs,
                                 const std::string& configuration, double cpPsi) {
    std::vector<TripletCurve> out;
    for (const TripletCurve& r : runs)
        if (r.configuration == configuration && r.cpPsi == cpPsi) out.push_back(r);
    return out;
}

FrictionCalibration calibrateFriction(const std::vector<TripletCurve>& runs,
                                      const CalibrationOptions& o) {
    FrictionCalibration result;
    result.options = o;
    std::vector<std::pair<std::string, double>> keys;
    std::vector<std::string> names;
    for (const TripletCurve& r : runs) {
        const auto key = std::make_pair(r.configuration, r.cpPsi);
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
        if (std::find(names.begin(), names.end(), r.configuration) == names.end())
            names.push_back(r.configuration);
    }
    std::sort(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
        const auto ia = std::find(names.begin(), names.end(), a.first) - names.begin();
        const auto ib = std::find(names.begin(), names.end(), b.first) - names.begin();
        return ia != ib ? ia < ib : a.second < b.second;
    });
    for (const auto& [name, cp] : keys)
        result.groups.push_back(calibrateGroup(runsOf(runs, name, cp), o));
    for (const std::string& name : names)
        result.configurations.push_back(calibrateConfiguration(name, result.groups, o));
    return result;
}

} // namespace kinstab
