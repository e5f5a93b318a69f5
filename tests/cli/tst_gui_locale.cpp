// SPDX-License-Identifier: GPL-3.0-or-later
// The desktop application in a German locale (decimal comma): it opens the shipped examples
// and runs them. QApplication sets the C locale from LANG, so any number parsed with the C
// library (std::stod) read "0.70" as 0 and refused the example's grid "0.70:1.15:0.05".

#include "CliRun.h"

#include <QImage>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QtTest>

#include <clocale>
#include <string>

namespace {

bool germanLocaleInstalled() {
    const std::string old = std::setlocale(LC_ALL, nullptr);
    const bool ok = std::setlocale(LC_ALL, "de_DE.UTF-8") != nullptr;
    std::setlocale(LC_ALL, old.c_str());
    return ok;
}

// kinstab PROJECT --screenshot FILE: opens, runs the sweep (or the record), saves, quits.
Run guiInGerman(const QString& project, const QString& png) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("LANG", "de_DE.UTF-8");
    env.insert("LC_ALL", "de_DE.UTF-8");
    env.insert("QT_QPA_PLATFORM", "offscreen");
    env.insert("QT_QPA_OFFSCREEN_NO_GLX", "1");
    p.setProcessEnvironment(env);
    p.start(KINSTAB_GUI, {project, "--screenshot", png});
    if (!p.waitForFinished(300000)) p.kill();
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

} // namespace

class TestGuiLocale : public QObject {
    Q_OBJECT
private slots:
    void opensAndRunsTheExamples_data() {
        QTest::addColumn<QString>("project");
        QTest::newRow("enveloped sine") << "paper-16-story.json";
        QTest::newRow("record") << "paper-16-story-record.json";
    }
    void opensAndRunsTheExamples() {
        if (!germanLocaleInstalled())
            QSKIP("locale de_DE.UTF-8 is not installed (scripts/install-deps.sh makes it)");
        QFETCH(QString, project);
        QTemporaryDir dir;
        const QString png = dir.filePath("window.png");
        const Run r = guiInGerman(KINSTAB_SOURCE_DIR "/resources/examples/" + project, png);
        QVERIFY2(r.code == 0, r.err.constData());
        QVERIFY(QImage(png).width() > 0);
    }
};

QTEST_GUILESS_MAIN(TestGuiLocale)
#include "tst_gui_locale.moc"
