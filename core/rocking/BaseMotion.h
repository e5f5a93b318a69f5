// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The motion of the base under a free-standing block, in physical time t (s): horizontal
// acceleration a_h(t) and vertical a_v(t), both in g (a_v > 0 upwards: gravity acts as
// g (1 + a_v)). The rocking solver integrates between piece ends, where the motion may have a
// kink or a jump, so its steps never straddle one; inside a piece both accelerations are smooth
// and either a_h is monotone or the motion finds its level crossings itself, so the initiation
// search at rest (firstExceedance) misses nothing.

#include "core/excitation/Excitation1D.h"

#include <limits>
#include <memory>

namespace kinstab {

class BaseMotion {
public:
    virtual ~BaseMotion() = default;
    virtual double horizontal(double t) const = 0; // g
    virtual double vertical(double /*t*/) const { return 0.0; }
    virtual bool hasVertical() const { return false; }
    // Time after which both accelerations are zero for good, s.
    virtual double end() const = 0;
    // The end of the smooth, monotone piece containing t (> t); inf after end().
    virtual double pieceEnd(double t) const = 0;
    // Largest |a_h|, g.
    virtual double peak() const = 0;
    // The first time in [t0, t1] (t1 <= pieceEnd(t0)) where
    //   sign * a_h(t) > level (1 + a_v(t)),
    // NaN when there is none. The default brackets on the ends of the piece (exact for a
    // monotone a_h and a_v linear in the piece) and bisects to machine precision.
    virtual double firstExceedance(int sign, double level, double t0, double t1) const;
};

// An Excitation1D of kinstab's other models (enveloped sine, recorded motion) in physical time:
// a_h(t) = e.accel(t / tstar), pieces the excitation's segments (a recorded motion's sample
// intervals; an enveloped sine's half-periods, one hump each, whose level crossings the
// excitation finds exactly). vertical, when given,
// is a second Excitation1D in the same time (a record's vertical component, g, > 0 upwards).
class ExcitationMotion final : public BaseMotion {
public:
    ExcitationMotion(std::shared_ptr<const Excitation1D> horizontal, double tstar, double endTime,
                     std::shared_ptr<const Excitation1D> vertical = {});
    double horizontal(double t) const override;
    double vertical(double t) const override;
    bool hasVertical() const override { return vertical_ != nullptr; }
    double end() const override { return end_; }
    double pieceEnd(double t) const override;
    double peak() const override { return horizontal_->peak(); }
    double firstExceedance(int sign, double level, double t0, double t1) const override;

private:
    std::shared_ptr<const Excitation1D> horizontal_;
    std::shared_ptr<const Excitation1D> vertical_;
    double tstar_;
    double end_;
};

// No base motion: free rocking from an initial tilt.
class NoMotion final : public BaseMotion {
public:
    double horizontal(double) const override { return 0.0; }
    double end() const override { return 0.0; }
    double pieceEnd(double) const override { return std::numeric_limits<double>::infinity(); }
    double peak() const override { return 0.0; }
};

} // namespace kinstab
