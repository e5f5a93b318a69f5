// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every numeric flag at the extremes a user can type (issues 31 and 32), shared by the CLI's
// property tests: the values tried for one declared input, and what each run must show.

#include "CliRun.h"

#include "core/base/NumberInput.h"

#include <QtTest>

#include <cmath>
#include <random>

// The values tried for one input: its range's ends and what lies just beyond them, the extremes
// of the double range, zero, -1, its default, and `draws` seeded log-uniform draws over the
// whole double range.
inline QList<double> extremeValues(const kinstab::NumberInput& in, std::mt19937_64& rng,
                                   int draws) {
    QList<double> v{in.range.lo,
                    in.range.hi,
                    in.range.lo * (1 - 1e-9),
                    in.range.hi * 1.001,
                    1e-300,
                    4.9e-324,
                    1e308,
                    0.0,
                    -1.0,
                    in.fallback};
    std::uniform_real_distribution<double> exponent(-320.0, 308.0);
    for (int k = 0; k < draws; ++k)
        v.push_back(std::pow(10.0, exponent(rng)));
    return v;
}

// The run ends in seconds with an answer (exit 0, no NaN) or a refusal (exit 2): never a hang,
// a crash or a bug's exit 1. Out of its range the value (the last but one argument's flag) is
// refused naming the flag; in range it runs unless another rule of core refuses the
// combination.
inline void verifyExtremeRun(const QStringList& args, bool inRange) {
    const TimedRun t = timedCli(args);
    const Run& r = t.r;
    QVERIFY2(t.answeredOrRefused(), t.exitText().constData());
    if (!inRange) {
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(args[args.size() - 2].toUtf8()), r.err.constData());
    }
    if (r.code == 0) QVERIFY2(!r.out.contains("NaN") && !r.out.contains("nan"), r.out.left(400));
}
