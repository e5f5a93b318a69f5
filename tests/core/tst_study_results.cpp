// SPDX-License-Identifier: GPL-3.0-or-later
// Study results read back (core/io/StudyResults.h): every row validated (types and ranges:
// a critical intensity of zero or less, or above the search limit, is refused); rows of two
// studies refused naming both fingerprints and lines; a shard out of case order named at its
// line, not reported as a missing case; a merge of more shards than the process may open.

#include "core/io/StudyResults.h"

#include <sys/resource.h>

#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace kinstab;

namespace {

const std::string kStudy = "0123456789abcdef", kOther = "fedcba9876543210";

StudyRow row(std::size_t index, std::size_t cases, const std::string& study = kStudy) {
    StudyRow r;
    r.index = index;
    r.cases = cases;
    r.study = study;
    r.set = index / 3;
    r.record = "r" + std::to_string(index % 3) + ".AT2";
    r.mu = 0.6;
    r.tstar = 0.099;
    r.limit = 1.0;
    r.measure = "pga";
    r.recordIntensity = 0.3;
    r.criticalIntensity = 0.5 + 1e-3 * static_cast<double>(index);
    r.criticalPeak = 1.0;
    r.limitIntensity = 2.0;
    r.runs = 10;
    return r;
}

std::string write(const QTemporaryDir& dir, const QString& name, const std::string& text) {
    const std::string path = dir.filePath(name).toStdString();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

std::string refusal(const std::string& line) {
    try {
        parseStudyRow(line);
    } catch (const StudyRowError& e) {
        return e.what();
    }
    return "accepted";
}

std::string mergeError(const std::vector<std::string>& shards) {
    try {
        mergeStudyShards(shards, [](std::string_view) {});
    } catch (const StudyRowError& e) {
        return e.what();
    }
    return "merged";
}

} // namespace

class TestStudyResults : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void rowsAreValidated_data() {
        QTest::addColumn<QByteArray>("from");
        QTest::addColumn<QByteArray>("to");
        QTest::addColumn<QByteArray>("refusal");
        QTest::newRow("zero critical")
            << QByteArray("\"critical_im_g\":0.5") << QByteArray("\"critical_im_g\":0")
            << QByteArray("\"critical_im_g\" = 0: expected a number > 0");
        QTest::newRow("negative critical")
            << QByteArray("\"critical_im_g\":0.5") << QByteArray("\"critical_im_g\":-0.5")
            << QByteArray("\"critical_im_g\" = -0.5");
        QTest::newRow("above the limit")
            << QByteArray("\"critical_im_g\":0.5") << QByteArray("\"critical_im_g\":2.5")
            << QByteArray("above \"limit_im_g\" = 2");
        QTest::newRow("critical without peak")
            << QByteArray("\"critical_peak_g\":1.0") << QByteArray("\"critical_peak_g\":null")
            << QByteArray("one without the other");
        QTest::newRow("zero mu") << QByteArray("\"mu\":0.6") << QByteArray("\"mu\":0")
                                 << QByteArray("\"mu\" = 0");
        QTest::newRow("text for a number")
            << QByteArray("\"tstar\":0.099") << QByteArray("\"tstar\":\"0.099\"")
            << QByteArray("\"tstar\": expected a number");
        QTest::newRow("no fingerprint")
            << QByteArray("\"study\":\"0123456789abcdef\",") << QByteArray()
            << QByteArray("\"study\": expected a string");
        QTest::newRow("not a fingerprint")
            << QByteArray("\"study\":\"0123456789abcdef\"") << QByteArray("\"study\":\"xyz\"")
            << QByteArray("expected the study's fingerprint");
        QTest::newRow("set after case") << QByteArray("\"set\":0") << QByteArray("\"set\":2")
                                        << QByteArray("\"set\": above \"case\"");
    }
    void rowsAreValidated() {
        QFETCH(QByteArray, from);
        QFETCH(QByteArray, to);
        QFETCH(QByteArray, refusal);
        QByteArray line = QByteArray::fromStdString(studyRowLine(row(0, 6)));
        QCOMPARE(QString::fromStdString(::refusal(line.toStdString())), QString("accepted"));
        QVERIFY2(line.contains(from), line.constData());
        line.replace(from, to);
        const std::string why = ::refusal(line.toStdString());
        QVERIFY2(why.find(refusal.toStdString()) != std::string::npos, why.c_str());
    }
    void twoStudiesAreNamed() {
        const std::string a = write(dir_, "a.jsonl", studyRowLine(row(0, 2)) + "\n");
        const std::string b = write(dir_, "b.jsonl", studyRowLine(row(1, 2, kOther)) + "\n");
        const std::string m = mergeError({a, b});
        QVERIFY2(m.find(b + ":1: a row of another study than " + a + ":1's") == 0, m.c_str());
        QVERIFY2(m.find(kStudy) != std::string::npos && m.find(kOther) != std::string::npos,
                 m.c_str());
        const std::string both =
            write(dir_, "both.jsonl",
                  studyRowLine(row(0, 2)) + "\n" + studyRowLine(row(1, 2, kOther)) + "\n");
        try {
            readStudyRows(both);
            QFAIL("rows of two studies were read as one");
        } catch (const StudyRowError& e) {
            QVERIFY2(std::string(e.what()).find(kOther) != std::string::npos, e.what());
        }
    }
    void aShardOutOfOrderIsNamedAtItsLine() {
        // Shard 1 of 2 holds cases 0, 2, 6, 4 (4 and 6 swapped); shard 2 is whole. Case 4 is
        // in no line in hand when the merge expects it: the shard's next line is named.
        std::string one, two;
        for (std::size_t i : {0, 2, 6, 4})
            one += studyRowLine(row(i, 8)) + "\n";
        for (std::size_t i : {1, 3, 5, 7})
            two += studyRowLine(row(i, 8)) + "\n";
        const std::string a = write(dir_, "one.jsonl", one), b = write(dir_, "two.jsonl", two);
        const std::string m = mergeError({a, b});
        QVERIFY2(m == a + ":4: case 4 is not after case 6: a shard is in case order", m.c_str());
        const std::string missing = mergeError({b});
        QVERIFY2(missing == "case 0 of 8 is in none of the shards", missing.c_str());
    }
    void mergesMoreShardsThanItMayOpen() {
        constexpr std::size_t kShards = 300;
        std::vector<std::string> shards;
        std::string whole;
        for (std::size_t k = 0; k < kShards; ++k) {
            std::string text; // two rows each: cases k and k + 300
            for (std::size_t i : {k, k + kShards})
                text += studyRowLine(row(i, 2 * kShards)) + "\n";
            shards.push_back(write(dir_, QString("s%1.jsonl").arg(k), text));
        }
        for (std::size_t i = 0; i < 2 * kShards; ++i)
            whole += studyRowLine(row(i, 2 * kShards)) + "\n";
        rlimit old{};
        QCOMPARE(::getrlimit(RLIMIT_NOFILE, &old), 0);
        rlimit low = old;
        low.rlim_cur = 64; // the test's own descriptors, and room for about 40 shards
        QCOMPARE(::setrlimit(RLIMIT_NOFILE, &low), 0);
        std::string merged;
        std::string error;
        try {
            mergeStudyShards(shards, [&](std::string_view t) { merged += t; });
        } catch (const StudyRowError& e) {
            error = e.what();
        }
        ::setrlimit(RLIMIT_NOFILE, &old);
        QVERIFY2(error.empty(), error.c_str());
        QVERIFY(merged == whole);
    }
};

QTEST_APPLESS_MAIN(TestStudyResults)
#include "tst_study_results.moc"
