// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/TripletCurve.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace kinstab {

std::string curveLabel(const TripletCurve& c) {
    std::ostringstream s;
    s << c.configuration << " CP " << c.cpPsi << " test " << c.test;
    return s.str();
}

std::string validateCurve(const TripletCurve& c) {
    const std::string who = curveLabel(c) + ": ";
    if (c.delta.size() != c.shear.size()) return who + "delta and shear differ in length";
    if (c.delta.size() < 3)
        return who + "needs at least 3 samples, has " + std::to_string(c.delta.size());
    for (Eigen::Index i = 0; i < c.delta.size(); ++i) {
        std::ostringstream s;
        s << who;
        if (!std::isfinite(c.delta(i)) || !std::isfinite(c.shear(i)))
            s << "sample " << i + 1 << " is not finite";
        else if (i > 0 && !(c.delta(i) > c.delta(i - 1)))
            s << "delta must increase, but " << c.delta(i) << " follows " << c.delta(i - 1);
        else if (!(c.shear(i) > 0.0))
            s << "shear must be positive, got " << c.shear(i) << " at delta " << c.delta(i);
        else
            continue;
        return s.str();
    }
    if (!(c.shear.tail(c.shear.size() - 1).minCoeff() < c.shear(0)))
        return who + "no post-peak decay (no sample below the first, " +
               std::to_string(c.shear(0)) + ")";
    return {};
}

TripletCurve compositeCurve(const std::vector<TripletCurve>& runs) {
    if (runs.empty()) throw std::invalid_argument("composite curve: no runs");
    TripletCurve mean = runs.front();
    mean.test.clear();
    mean.shear.setZero();
    for (const TripletCurve& r : runs) {
        if (r.delta.size() != mean.delta.size() || !r.delta.isApprox(mean.delta, 1e-9))
            throw std::invalid_argument(curveLabel(r) +
                                        ": displacements differ from those of test " +
                                        runs.front().test + "; a composite needs one delta grid");
        mean.shear += r.shear;
        mean.test += (mean.test.empty() ? "" : ",") + r.test;
    }
    mean.shear /= static_cast<double>(runs.size());
    return mean;
}

} // namespace kinstab
