// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/FloorMotions.h"

#include "core/excitation/FloorFilter.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace kinstab {

std::vector<Accelerogram> floorMotions(const ModalModel& model, const Accelerogram& ground,
                                       const FloorMotionOptions& options) {
    validateAccelerogram(ground);
    if (model.modes.empty()) throw std::invalid_argument("the building has no modes");
    const FloorFilterParams first{model.modes.front().period, options.damping, options.tail};
    if (const std::string e = validateFloorFilter(first); !e.empty())
        throw std::invalid_argument("floors: " + e);
    std::vector<double> input = ground.samples;
    input.resize(input.size() +
                     static_cast<std::size_t>(std::ceil(floorTailSeconds(first) / ground.dt)),
                 0.0);
    const std::size_t levels = model.modes.front().shape.size();
    std::vector<std::vector<double>> a(levels, std::vector<double>(input.size(), 0.0));
    for (const Mode& m : model.modes) {
        const std::vector<double> modal =
            floorAcceleration(input, ground.dt, m.period, options.damping);
        for (std::size_t i = 0; i < levels; ++i) {
            const double gp = m.participation * m.shape[i];
            for (std::size_t k = 0; k < input.size(); ++k)
                a[i][k] += gp * modal[k];
        }
    }
    std::vector<Accelerogram> out;
    for (std::size_t i = 0; i < levels; ++i) {
        Accelerogram level = ground;
        level.samples = std::move(a[i]);
        std::ostringstream name;
        name << "level " << i + 1 << " of " << levels << " (shear building, " << model.modes.size()
             << " modes, damping " << 100.0 * options.damping << " %) under "
             << (ground.name.empty() ? ground.sourceFile : ground.name);
        level.name = name.str();
        level.format = "shear building";
        level.headerPeak.reset();
        out.push_back(std::move(level));
    }
    return out;
}

std::vector<double> peakAccelerations(const std::vector<Accelerogram>& motions) {
    std::vector<double> p;
    for (const Accelerogram& m : motions)
        p.push_back(std::abs(m.peak().value));
    return p;
}

} // namespace kinstab
