// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs kinstab-cli (or another program) as a user would, for the cli tests.

#include <QByteArray>
#include <QElapsedTimer>
#include <QProcess>
#include <QStringList>

struct Run {
    int code = -1; // exit code; -1 when the program crashed or timed out
    QByteArray out, err;
};

inline Run run(const QString& program, const QStringList& args, int timeoutMs = 300000) {
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(timeoutMs)) { // a hang: killed, and never taken for an exit 0
        p.kill();
        p.waitForFinished();
        return {-1, p.readAllStandardOutput(), p.readAllStandardError()};
    }
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

inline Run cli(const QStringList& args) {
    return run(KINSTAB_CLI, args);
}

// kinstab-cli at an extreme input (issues 31 and 32): the run, its wall time, and the text a
// failed check shows. Such a run must end with exit 0 (an answer) or 2 (a refusal); one still
// running after 30 s is a hang, killed and reported as exit -1. How long a run takes is measured
// by `kinstab-cli bench`, not asserted here (CONTRIBUTING.md).
struct TimedRun {
    Run r;
    qint64 ms = 0;
    bool answeredOrRefused() const { return r.code == 0 || r.code == 2; }
    QByteArray exitText() const {
        return QString("exit %1 after %2 ms: %3").arg(r.code).arg(ms).arg(r.err).toUtf8();
    }
};

inline TimedRun timedCli(const QStringList& args) {
    QElapsedTimer clock;
    clock.start();
    Run r = run(KINSTAB_CLI, args, 30000);
    return {r, clock.elapsed()};
}
