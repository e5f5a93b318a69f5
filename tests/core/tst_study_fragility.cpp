// SPDX-License-Identifier: GPL-3.0-or-later
// The lognormal collapse fragility of a study (docs/studies.md):
//  - without censoring the maximum-likelihood fit has a closed form: the median is exp(mean of
//    ln x) and beta the standard deviation of ln x with divisor n;
//  - with censored records it agrees with a brute-force maximization of the same likelihood
//    over a grid, refined around the best cell;
//  - a synthetic suite drawn at the quantiles of a known lognormal (median 0.8 g, beta 0.4),
//    censored at 1.2 g, gives back its median and beta;
//  - the seeded bootstrap is reproducible and its bounds bracket the fit;
//  - the empirical points are the Kaplan-Meier estimate: censored records count in the total
//    (all censored above the collapses: rank / records), and a record censored below a collapse
//    leaves the records at risk there (tst_kaplan_meier works the product by hand).

#include "core/io/FragilityText.h"
#include "core/study/Fragility.h"
#include "core/study/LognormalFit.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace kinstab;

namespace {

// Phi^-1(p) by bisection on the normal CDF (independent of the code under test).
double normalQuantile(double p) {
    double lo = -10, hi = 10;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::numbers::sqrt2) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

struct Best {
    double m, beta, ll;
};

// Brute force: the best cell of an n x n grid, then the grid shrunk around it, ten times.
Best bruteForce(const CensoredSample& s, double m0, double m1, double b0, double b1) {
    Best best{0, 0, -INFINITY};
    const int n = 60;
    for (int round = 0; round < 10; ++round) {
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const double m = m0 + (m1 - m0) * i / n, b = b0 + (b1 - b0) * j / n;
                const double ll = lognormalLogLikelihood(s, m, b);
                if (ll > best.ll) best = {m, b, ll};
            }
        const double dm = 2 * (m1 - m0) / n, db = 2 * (b1 - b0) / n;
        m0 = best.m - dm, m1 = best.m + dm;
        b0 = std::max(1e-3, best.beta - db), b1 = best.beta + db;
    }
    return best;
}

StudyRow row(std::size_t index, double critical, double limitIm) {
    StudyRow r;
    r.index = index;
    r.record = "r" + std::to_string(index);
    if (critical > 0) r.criticalIntensity = critical;
    r.limitIntensity = limitIm;
    return r;
}

} // namespace

class TestStudyFragility : public QObject {
    Q_OBJECT
private slots:
    void noCensoringIsTheSampleMeanAndDeviationOfLogs() {
        const CensoredSample s{{0.31, 0.45, 0.52, 0.60, 0.77, 1.10, 1.42}, {}};
        double mean = 0, var = 0;
        for (double x : s.collapsed)
            mean += std::log(x) / 7.0;
        for (double x : s.collapsed)
            var += std::pow(std::log(x) - mean, 2) / 7.0;
        const auto f = fitLognormal(s);
        QVERIFY(f);
        QCOMPARE_LT(std::abs(std::log(f->median) - mean), 1e-7);
        QCOMPARE_LT(std::abs(f->beta - std::sqrt(var)), 1e-7);
    }
    void censoredFitIsTheLikelihoodMaximum() {
        // Four records do not collapse up to the search limit (their limit intensities differ,
        // as the unscaled records' peaks do).
        const CensoredSample s{{0.42, 0.55, 0.58, 0.71, 0.93, 1.05}, {1.1, 1.2, 1.2, 1.4}};
        const auto f = fitLognormal(s);
        QVERIFY(f);
        const Best b = bruteForce(s, -3, 3, 0.01, 3);
        QCOMPARE_LT(std::abs(std::log(f->median) - b.m), 1e-6);
        QCOMPARE_LT(std::abs(f->beta - b.beta), 1e-6);
        QVERIFY(f->logLikelihood >= b.ll - 1e-9);
        // Censoring moves the median up: the uncensored fit of the collapses alone is lower.
        QVERIFY(f->median > fitLognormal({s.collapsed, {}})->median);
    }
    void syntheticSuiteRecoversMedianAndBeta() {
        const double median = 0.8, beta = 0.4, limit = 1.2;
        const int n = 4000;
        CensoredSample s;
        for (int i = 1; i <= n; ++i) {
            const double x = median * std::exp(beta * normalQuantile((i - 0.5) / n));
            (x <= limit ? s.collapsed : s.censored).push_back(x <= limit ? x : limit);
        }
        QVERIFY(s.censored.size() > 500); // a real share is censored (P(x > 1.2) = 0.156)
        const auto f = fitLognormal(s);
        QVERIFY(f);
        // Quantile points, not a random draw: the only error is the discreteness of n points.
        QCOMPARE_LT(std::abs(f->median / median - 1), 2e-3);
        QCOMPARE_LT(std::abs(f->beta / beta - 1), 5e-3);
    }
    void noFitWithoutTwoCollapses() {
        std::string why;
        QVERIFY(!fitLognormal({{0.5}, {1.0, 1.0}}, &why));
        QVERIFY(why.find("two distinct") != std::string::npos);
        QVERIFY(!fitLognormal({{0.5, 0.5}, {}}, &why));
        QVERIFY(!fitLognormal({{0.5, 0.6}, {-1.0}}, &why));
    }
    void bootstrapIsSeededAndBracketsTheFit() {
        std::vector<StudyRow> rows;
        const double crit[] = {0.42, 0.55, 0.58, 0.71, 0.93, 1.05, 0.66, 0.81, 0, 0};
        for (std::size_t i = 0; i < 10; ++i)
            rows.push_back(row(i, crit[i], 1.3));
        const BootstrapSettings b{400, 7, 0.9};
        const Fragility f = fragilityOf(rows, b);
        QVERIFY(f.fit);
        QCOMPARE(f.records, std::size_t(10));
        QCOMPARE(f.collapsed, std::size_t(8));
        QVERIFY(f.fitted > 350); // a resample with < 2 distinct collapses has no fit
        QVERIFY(*f.medianLower < f.fit->median && f.fit->median < *f.medianUpper);
        QVERIFY(*f.betaLower < f.fit->beta && f.fit->beta < *f.betaUpper);
        QVERIFY(!f.medianBeyondSearch && !f.betaAtBound);
        const Fragility again = fragilityOf(rows, b);
        QCOMPARE(again.medianLower, f.medianLower);
        QCOMPARE(again.betaUpper, f.betaUpper);
        const Fragility other = fragilityOf(rows, {400, 8, 0.9});
        QVERIFY(other.medianLower != f.medianLower);
        for (const auto& c : f.curve)
            QVERIFY(0 <= *c.lower && *c.lower <= c.probability && c.probability <= *c.upper &&
                    *c.upper <= 1);
        // Empirical points: 8 collapses of 10 records, the last at 8/10.
        QCOMPARE(f.points.size(), std::size_t(8));
        QCOMPARE(f.points.front().intensity, 0.42);
        QCOMPARE(f.points.back().probability, 0.8);
    }
    // Issue 30: 2 collapses among 30 records. Most resamples draw fewer than two distinct
    // collapses and cannot be fitted; they are the ones whose median lies beyond the data, so
    // dropping them biased the upper bound down onto the estimate. Counted as medians beyond
    // the data, the upper bound is open and the interval contains the estimate.
    void bootstrapCountsUnfittedResamplesAsBeyondTheData() {
        std::vector<StudyRow> rows;
        for (std::size_t i = 0; i < 30; ++i)
            rows.push_back(row(i, i == 3 ? 2.1 : i == 17 ? 2.8 : 0.0, 3.0));
        const Fragility f = fragilityOf(rows, {1000, 1, 0.9});
        QVERIFY(f.fit);
        QVERIFY(f.fitted < f.resamples);
        QVERIFY(*f.medianLower <= f.fit->median && f.fit->median <= *f.medianUpper);
        QVERIFY(std::isinf(*f.medianUpper)); // over 5 % of the resamples have no fit
        // The median lies above every search limit (3 g): an extrapolation, said so.
        QCOMPARE(f.searchTop, 3.0);
        QCOMPARE(f.medianBeyondSearch, f.fit->median > 3.0);
    }
    void recordStatisticsOverTheCollapses() {
        // Collapses at 0.4, 0.5, 0.8 g, one record censored: mean 1.7/3 = 0.566667 g, median
        // 0.5 g, std sqrt(((0.4-m)^2 + (0.5-m)^2 + (0.8-m)^2) / 2) = sqrt(0.086667 / 2) = 0.208167
        // g; ln: mean (ln 0.4 + ln 0.5 + ln 0.8) / 3 = ln(0.16) / 3 = -0.610860, deviations
        // -0.305430, -0.082286, 0.387717, squares summing to 0.250383: std sqrt(0.250383 / 2) =
        // 0.353824 (by hand).
        const std::vector<StudyRow> rows = {row(0, 0.8, 2), row(1, 0.4, 2), row(2, 0, 2),
                                            row(3, 0.5, 2)};
        const RecordStatistics s = fragilityOf(rows, {0, 1, 0.9}).statistics;
        QCOMPARE(s.collapsed, std::size_t(3));
        QCOMPARE(s.censored, std::size_t(1));
        QCOMPARE_LE(std::abs(*s.meanG - 1.7 / 3), 1e-15);
        QCOMPARE(*s.medianG, 0.5);
        QCOMPARE_LE(std::abs(*s.stdG - 0.208167), 1e-6);
        QCOMPARE_LE(std::abs(*s.meanLn - std::log(0.16) / 3), 1e-15);
        QCOMPARE_LE(std::abs(*s.stdLn - 0.353824), 1e-6);
        // One collapse: no deviation; none: nothing but the counts.
        const RecordStatistics one =
            fragilityOf({row(0, 0.8, 2), row(1, 0, 2)}, {0, 1, 0.9}).statistics;
        QVERIFY(one.meanG && !one.stdG && !one.stdLn);
        const RecordStatistics none = fragilityOf({row(0, 0, 2)}, {0, 1, 0.9}).statistics;
        QVERIFY(!none.meanG && none.censored == 1);
    }
    // Issue 31: the bootstrap runs on core's thread pool with the same bits whatever the thread
    // count, and they are those of the plain loop docs/studies.md describes: resample k takes
    // the k-th block of `records` outputs of one mt19937_64 stream, index = output mod records.
    // 1001 resamples do not divide into the pool's chunks evenly.
    void bootstrapIsTheSameOnAnyNumberOfThreads() {
        std::vector<StudyRow> rows;
        for (std::size_t i = 0; i < 40; ++i)
            rows.push_back(row(i, i % 7 == 6 ? 0.0 : 0.3 + 0.037 * double((i * 17) % 40), 1.8));
        const BootstrapSettings one{1001, 11, 0.9, 1};
        const Fragility f = fragilityOf(rows, one);
        QVERIFY(f.fit && f.medianLower && f.betaUpper);
        for (int threads : {2, 3, 8, 0}) {
            BootstrapSettings b = one;
            b.threads = threads;
            const Fragility g = fragilityOf(rows, b);
            QCOMPARE(g.fitted, f.fitted);
            QCOMPARE(*g.medianLower, *f.medianLower); // bit for bit
            QCOMPARE(*g.medianUpper, *f.medianUpper);
            QCOMPARE(*g.betaLower, *f.betaLower);
            QCOMPARE(*g.betaUpper, *f.betaUpper);
            for (std::size_t c = 0; c < f.curve.size(); ++c)
                QVERIFY(*g.curve[c].lower == *f.curve[c].lower &&
                        *g.curve[c].upper == *f.curve[c].upper);
        }
        // The plain loop: every resample's median, sorted, at the 5 % and 95 % positions.
        std::mt19937_64 rng(11);
        std::vector<double> medians;
        for (int k = 0; k < 1001; ++k) {
            CensoredSample s;
            for (std::size_t i = 0; i < rows.size(); ++i) {
                const StudyRow& r = rows[rng() % rows.size()];
                (r.criticalIntensity ? s.collapsed : s.censored)
                    .push_back(r.criticalIntensity.value_or(r.limitIntensity));
            }
            const auto fit = fitLognormal(s);
            medians.push_back(fit ? fit->median : INFINITY);
        }
        std::sort(medians.begin(), medians.end());
        // Linear between order statistics, at (1 - level) / 2 and its complement.
        auto quantile = [&](double q) {
            const double pos = q * double(medians.size() - 1);
            const auto i = std::size_t(pos);
            const double w = pos - double(i), a = medians[i], b = medians[i + 1];
            return w == 0 || a == b ? a : std::isinf(b) ? b : a + w * (b - a);
        };
        const double lo = 0.5 * (1 - 0.9);
        QCOMPARE(*f.medianLower, std::min(quantile(lo), f.fit->median));
        QCOMPARE(*f.medianUpper, std::max(quantile(1 - lo), f.fit->median));
    }
    // The work of one set's bootstrap is bounded (kMaxBootstrapDraws = 1000 resamples of the
    // largest suite a study holds); beyond it the set is refused, saying what would fit.
    void bootstrapWorkIsBounded() {
        QCOMPARE(kMaxBootstrapDraws, std::size_t(10'000'000));
        QCOMPARE(bootstrapWorkError(kMaxStudyRecords, {}), std::string());
        QCOMPARE(bootstrapWorkError(20'000, {}),
                 std::string("1000 resamples x 20000 records of the set = 2e+07 draws, more "
                             "than the limit of 1e+07: at most 500 resamples (or 0)"));
        QCOMPARE(bootstrapWorkError(20'000, {500, 1, 0.9, 0}), std::string());
        std::vector<StudyRow> rows;
        for (std::size_t i = 0; i < 20'000; ++i)
            rows.push_back(row(i, 0.5 + 1e-5 * double(i), 2.0));
        QVERIFY_THROWS_EXCEPTION(StudyError, fragilityOf(rows, {}));
        QVERIFY(fragilityOf(rows, {0, 1, 0.9, 0}).fit); // no bootstrap: the fit alone
    }
    void noBootstrapNoBounds() {
        std::vector<StudyRow> rows;
        const double crit[] = {0.42, 0.55, 0.58, 0.71, 0.93};
        for (std::size_t i = 0; i < 5; ++i)
            rows.push_back(row(i, crit[i], 1.3));
        const Fragility f = fragilityOf(rows, {0, 1, 0.9});
        QVERIFY(f.fit && !f.medianLower && !f.betaLower);
        for (const auto& c : f.curve)
            QVERIFY(!c.lower && !c.upper);
    }
    void betaAtTheSearchBoundIsSaid() {
        // Two collapses a factor 1e6 apart: the likelihood rises toward ever larger beta.
        std::vector<StudyRow> rows = {row(0, 1e-3, 1e4), row(1, 1e3, 1e4)};
        const Fragility f = fragilityOf(rows, {0, 1, 0.9});
        QVERIFY(f.fit);
        QCOMPARE(f.betaAtBound, betaAtBound(f.fit->beta));
        QVERIFY2(f.betaAtBound, qPrintable(QString::number(f.fit->beta)));
    }
    // CSV text cells cannot break a row or run as a spreadsheet formula (issue 31: a shard could
    // inject a line break and =HYPERLINK(...) through measure or motion).
    void csvQuotesAndNeutralisesText() {
        std::vector<StudyRow> rows = {row(0, 0.5, 2.0), row(1, 0.7, 2.0)};
        for (StudyRow& r : rows) {
            r.measure = "=HYPERLINK(\"x\",\"y\")";
            r.motion = "a\nb";
        }
        const std::string csv = fragilityCsv({fragilityOf(rows, {0, 1, 0.9})});
        QCOMPARE(std::count(csv.begin(), csv.end(), '\n'),
                 std::ptrdiff_t(3)); // header, row, "a\nb"
        QVERIFY(csv.find(",\"'=HYPERLINK(\"\"x\"\",\"\"y\"\")\",") != std::string::npos);
        QVERIFY(csv.find(",\"a\nb\"") != std::string::npos);
        QVERIFY(csv.find(",=") == std::string::npos);
    }
    void pointsCensoredBelowACollapseAreKaplanMeier() {
        // Collapses at 0.2, 0.4, 0.5, 0.8 g; censored at 0.3 and 0.6 g: F = 1/6, 3/8, 7/12, 1
        // (the product written out in tst_kaplan_meier), not hits / total (1/6, 2/6, 3/6, 4/6).
        const double crit[] = {0.8, 0.2, 0, 0.5, 0.4, 0};
        const double limit[] = {2, 2, 0.3, 2, 2, 0.6};
        std::vector<StudyRow> rows;
        for (std::size_t i = 0; i < 6; ++i)
            rows.push_back(row(i, crit[i], limit[i]));
        const Fragility f = fragilityOf(rows, {20, 1, 0.9});
        QCOMPARE(f.points.size(), std::size_t(4));
        const double p[] = {1.0 / 6, 3.0 / 8, 7.0 / 12, 1.0};
        for (std::size_t i = 0; i < 4; ++i)
            QCOMPARE_LT(std::abs(f.points[i].probability - p[i]), 1e-15);
        QCOMPARE(f.points[1].record, std::string("r4"));
    }
    void setsAreGroupedInOrder() {
        std::vector<StudyRow> rows;
        for (std::size_t i = 0; i < 6; ++i) {
            StudyRow r = row(i, 0.4 + 0.1 * double(i % 3) + 0.01 * double(i), 2.0);
            r.set = i / 3;
            rows.push_back(r);
        }
        const auto sets = studyFragility(rows, {50, 1, 0.9});
        QCOMPARE(sets.size(), std::size_t(2));
        QCOMPARE(sets[1].parameters.set, std::size_t(1));
        QCOMPARE(sets[1].records, std::size_t(3));
    }
};

QTEST_APPLESS_MAIN(TestStudyFragility)
#include "tst_study_fragility.moc"
