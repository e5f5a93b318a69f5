// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs kinstab-cli (or another program) as a user would, for the cli tests.

#include <QByteArray>
#include <QProcess>
#include <QStringList>

struct Run {
    int code = -1; // exit code; -1 when the program crashed or timed out
    QByteArray out, err;
};

inline Run run(const QString& program, const QStringList& args, int timeoutMs = 300000) {
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(timeoutMs)) p.kill();
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

inline Run cli(const QStringList& args) {
    return run(KINSTAB_CLI, args);
}
