// SPDX-License-Identifier: GPL-3.0-or-later
// RecordPreview (ui): loads shipped records from the Qt resources, plots ground, |floor| with
// its fitted envelope, and the normalized spectra; a broken file leaves a line-numbered
// message and the previous record. Offscreen; saves a screenshot for inspection.

#include "ui/RecordPreview.h"

#include <QDir>
#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtCharts/QChart>
#include <QtCharts/QLineSeries>
#include <QtTest>

using namespace kinstab;
using kinstab::ui::RecordPreview;

namespace {

QLineSeries* seriesAt(QChart* c, int i) {
    return qobject_cast<QLineSeries*>(c->series().value(i));
}

// Frequency of the largest point of a spectrum series.
double peakFrequency(QLineSeries* s) {
    QPointF best(0, -1);
    for (const QPointF& p : s->points())
        if (p.y() > best.y()) best = p;
    return best.x();
}

} // namespace

class TestRecordPreview : public QObject {
    Q_OBJECT
private slots:
    void loadsResourceAndPlotsFloorMotion();
    void floorFilterOffAndRetuned();
    void brokenFileKeepsPreviousRecord();
    void defaultVerticalIsNamed();
    void decimationKeepsExtremes();
    void metricsShownWithSaAtThePeriod();
    void screenshot();
};

void TestRecordPreview::loadsResourceAndPlotsFloorMotion() {
    RecordPreview w;
    QSignalSpy spy(&w, &RecordPreview::recordChanged);
    QVERIFY2(w.loadFile(":/records/RSN77_SFERN_PUL164.AT2"), qPrintable(w.errorText()));
    QCOMPARE(spy.count(), 1);
    QCOMPARE(w.record()->size(), std::size_t(4172)); // SOURCES.md §1
    QVERIFY(w.floorMotion().has_value());
    QCOMPARE(w.groundChart()->series().size(), 1);
    QVERIFY(seriesAt(w.groundChart(), 0)->count() <= 2 * 1500 + 4);
    QCOMPARE(w.floorChart()->series().size(), 2); // |floor| and the envelope
    QCOMPARE(w.spectrumChart()->series().size(), 2);
    // Default filter T = 1 s, 2 %: the floor spectrum peaks at 1 Hz (paper Fig. 26).
    const double df = 1.0 / (8192 * 0.01);
    QCOMPARE_LE(std::abs(peakFrequency(seriesAt(w.spectrumChart(), 1)) - 1.0), df);
    QVERIFY(w.envelope()->beta > w.envelope()->alpha);
}

void TestRecordPreview::floorFilterOffAndRetuned() {
    RecordPreview w;
    QVERIFY(w.loadFile(":/records/RSN77_SFERN_PUL164.AT2"));
    w.setFloorFilter(std::nullopt);
    QVERIFY(!w.floorMotion().has_value());
    QCOMPARE(w.spectrumChart()->series().size(), 1);
    QVERIFY(w.floorChart()->title().contains("floor filter off"));
    w.setFloorFilter(FloorFilterParams{0.5, 0.05, std::nullopt});
    QCOMPARE(w.floorFilter()->period, 0.5);
    // The floor spectrum now peaks inside the oscillator's half-power band, 2 Hz (1 +- zeta).
    QCOMPARE_LE(std::abs(peakFrequency(seriesAt(w.spectrumChart(), 1)) - 2.0), 0.05 * 2.0);
}

void TestRecordPreview::brokenFileKeepsPreviousRecord() {
    RecordPreview w;
    QVERIFY(w.loadFile(":/records/RSN68_SFERN_PEL-UP.AT2"));
    QTemporaryDir dir;
    const QString path = dir.filePath("broken.AT2");
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("PEER NGA STRONG MOTION DATABASE RECORD\nX, 1/1/2000, Y, 90\nACCELERATION TIME SERIES "
            "IN UNITS OF G\n"
            "NPTS= 4, DT= .01 SEC\n .1E-02 .2E-02 nan\n");
    f.close();
    QVERIFY(!w.loadFile(path));
    QVERIFY2(w.errorText().contains("broken.AT2:5:"), qPrintable(w.errorText()));
    QCOMPARE(w.record()->size(), std::size_t(7945));
    QVERIFY(!w.loadFile(dir.filePath("missing.AT2")));
    QVERIFY(w.errorText().contains("cannot open"));
}

void TestRecordPreview::defaultVerticalIsNamed() {
    RecordPreview w;
    QVERIFY(w.loadFile(RecordPreview::defaultVerticalRecord()));
    QCOMPARE(QString::fromStdString(w.record()->component), QString("UP"));
    QVERIFY(RecordPreview::defaultVerticalNote().contains("Pacoima Dam vertical"));
}

void TestRecordPreview::decimationKeepsExtremes() {
    std::vector<double> y(42000);
    for (std::size_t i = 0; i < y.size(); ++i)
        y[i] = std::sin(0.01 * static_cast<double>(i)) * (i == 31234 ? 5.0 : 1.0);
    const QList<QPointF> d = report::decimatedSeries(y, 0.005, 1500);
    QVERIFY(d.size() <= 2 * 1500 + 4);
    double top = -1e9, bottom = 1e9;
    for (const QPointF& p : d) {
        top = std::max(top, p.y());
        bottom = std::min(bottom, p.y());
    }
    QCOMPARE(top, *std::max_element(y.begin(), y.end()));
    QCOMPARE(bottom, *std::min_element(y.begin(), y.end()));
}

// Issue 35: the record's catalogue numbers on import, Sa at the period T of the floor filter's
// field (the building's). El Centro 1940 (RSN 6, 180): the NumPy figures of
// tests/core/tst_record_metrics.cpp (PGA 0.2807955 g, PGV 0.309286895 m/s, Arias 1.541858564
// m/s, D5-95 24.18830614 s, Tm 0.5787257477 s, Sa(1 s) 0.4728542132 g, Sa(2 s) 0.1985421415 g),
// shown to three digits.
void TestRecordPreview::metricsShownWithSaAtThePeriod() {
    RecordPreview w;
    QVERIFY(w.loadFile(KINSTAB_SOURCE_DIR "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2"));
    QVERIFY(w.metrics().has_value());
    QCOMPARE(w.metrics()->sa->period, 1.0);
    QCOMPARE_LT(std::abs(w.metrics()->sa->g - 0.4728542132), 1e-9);
    const QString info = w.findChild<QLabel*>("recordInfo")->text();
    for (const char* shown : {"PGA 0.281 g", "PGV 30.9 cm/s", "Arias 1.54 m/s", "D5–95 24.2 s",
                              "Tm 0.579 s", "Sa(1 s, 5 %) 0.473 g"})
        QVERIFY2(info.contains(QString::fromUtf8(shown)), qPrintable(info));
    w.setFloorFilter(FloorFilterParams{2.0, 0.02, std::nullopt});
    QCOMPARE_LT(std::abs(w.metrics()->sa->g - 0.1985421415), 1e-9);
    QVERIFY(w.findChild<QLabel*>("recordInfo")->text().contains("Sa(2 s, 5 %) 0.199 g"));
    w.clear();
    QVERIFY(!w.metrics().has_value());
}

void TestRecordPreview::screenshot() {
    RecordPreview w;
    QVERIFY(w.loadFile(":/records/RSN77_SFERN_PUL164.AT2"));
    w.resize(1100, 950);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const QString out =
        qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR", QDir::tempPath()) + "/record_preview.png";
    const QImage image = w.grab().toImage();
    QVERIFY(image.save(out));
    // Not blank: the charts drew lines in more than one colour.
    QSet<QRgb> colours;
    for (int y = 0; y < image.height(); y += 7)
        for (int x = 0; x < image.width(); x += 7)
            colours.insert(image.pixel(x, y));
    QVERIFY(colours.size() > 20);
}

QTEST_MAIN(TestRecordPreview)
#include "tst_record_preview.moc"
