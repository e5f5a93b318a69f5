// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli links core only (issue 34): no Qt library at all, so that a compute command starts
// without the dynamic loader's work on Qt. Its report command runs kinstab-report, which links
// core and the report library only (issue 15): it writes reports through Qt Gui, so neither that
// executable nor any library it loads may be Qt Widgets, Charts, Data Visualization, Qml, Quick
// or OpenGL; nor Qt Concurrent, since core's thread pool runs the report's analyses. Reads the
// loader's view of each binary with ldd (libc-bin) and its own NEEDED entries with readelf
// (binutils).

#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

namespace {

const QRegularExpression kAnyQt(QStringLiteral("libQt6[A-Za-z]+"));
const QRegularExpression
    kForbidden(QStringLiteral("Qt6(Widgets|Charts|DataVisualization|Qml|Quick|OpenGL|Concurrent)"));

QString run(const QString& program, const QStringList& args) {
    QProcess p;
    p.start(program, args);
    if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
    return QString::fromUtf8(p.readAllStandardOutput());
}

} // namespace

class TestCliLink : public QObject {
    Q_OBJECT
private slots:
    void cliLoadsNoQt();
    void cliNeedsNoQt();
    void reportLoadsNoWidgetLibrary();
    void reportNeedsNoWidgetLibrary();
};

// Every shared library the loader maps for kinstab-cli, direct or indirect.
void TestCliLink::cliLoadsNoQt() {
    const QString libs = run(QStringLiteral("ldd"), {QStringLiteral(KINSTAB_CLI)});
    QVERIFY2(libs.contains(QStringLiteral("libstdc++")), qPrintable(libs)); // ldd worked
    const QRegularExpressionMatch m = kAnyQt.match(libs);
    QVERIFY2(!m.hasMatch(), qPrintable("kinstab-cli loads " + m.captured(0) + ":\n" + libs));
}

// The libraries the executable itself names.
void TestCliLink::cliNeedsNoQt() {
    const QString dynamic = run(QStringLiteral("readelf"), {"-d", QStringLiteral(KINSTAB_CLI)});
    QVERIFY2(dynamic.contains(QStringLiteral("NEEDED")), qPrintable(dynamic));
    const QRegularExpressionMatch m = kAnyQt.match(dynamic);
    QVERIFY2(!m.hasMatch(), qPrintable("kinstab-cli needs " + m.captured(0) + ":\n" + dynamic));
}

void TestCliLink::reportLoadsNoWidgetLibrary() {
    const QString libs = run(QStringLiteral("ldd"), {QStringLiteral(KINSTAB_REPORT)});
    QVERIFY2(libs.contains(QStringLiteral("libQt6Gui")), qPrintable(libs)); // ldd worked
    const QRegularExpressionMatch m = kForbidden.match(libs);
    QVERIFY2(!m.hasMatch(), qPrintable("kinstab-report loads " + m.captured(0) + ":\n" + libs));
}

void TestCliLink::reportNeedsNoWidgetLibrary() {
    const QString dynamic = run(QStringLiteral("readelf"), {"-d", QStringLiteral(KINSTAB_REPORT)});
    QVERIFY2(dynamic.contains(QStringLiteral("NEEDED")), qPrintable(dynamic));
    const QRegularExpressionMatch m = kForbidden.match(dynamic);
    QVERIFY2(!m.hasMatch(), qPrintable("kinstab-report needs " + m.captured(0) + ":\n" + dynamic));
}

QTEST_GUILESS_MAIN(TestCliLink)
#include "tst_cli_link.moc"
