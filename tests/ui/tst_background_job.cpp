// SPDX-License-Identifier: GPL-3.0-or-later
// ui/BackgroundJob (issue #15): the one way the GUI runs work off its thread. A cancel reaches
// the work and its result still comes back once; destroying the job while it runs cancels and
// waits, and nothing is delivered afterwards; a job superseded by a newer start() never
// delivers; progress is polled, not sent per unit; a throw comes back as failed().

#include "ui/BackgroundJob.h"

#include <QSignalSpy>
#include <QtTest>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>

using namespace kinstab::ui;

namespace {

// Work that counts until it is cancelled (bounded: it gives up after 30 s) and returns the count,
// or -1 when nobody cancelled it.
int countUntilCancelled(JobContext& job) {
    for (int i = 0; i < 30000; ++i) {
        if (job.isCancelled()) return static_cast<int>(job.done.load());
        ++job.done;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return -1;
}

} // namespace

class TestBackgroundJob : public QObject {
    Q_OBJECT

private slots:
    void cancelReachesTheWorkAndDeliversOnce() {
        BackgroundJob job(nullptr, 20);
        std::vector<int> delivered;
        job.start<int>(countUntilCancelled, [&](int n) { delivered.push_back(n); });
        QVERIFY(job.isRunning());
        QTRY_VERIFY_WITH_TIMEOUT(job.context()->done > 0, 10000);
        QSignalSpy ended(&job, &BackgroundJob::ended);
        job.cancel();
        QVERIFY(ended.wait(10000));
        QVERIFY(!job.isRunning());
        QCOMPARE(delivered.size(), 1u);
        QVERIFY(delivered[0] > 0); // stopped by the cancel, not by the 30 s bound
        QTest::qWait(100);
        QCOMPARE(delivered.size(), 1u); // once
    }

    void destructionWhileRunningCancelsWaitsAndDropsTheResult() {
        auto delivered = std::make_shared<int>(0);
        std::shared_ptr<JobContext> context;
        {
            auto* job = new BackgroundJob(nullptr, 20);
            job->start<int>(countUntilCancelled, [delivered](int) { ++*delivered; });
            context = job->context();
            QTRY_VERIFY_WITH_TIMEOUT(context->done > 0, 10000);
            delete job; // must not crash, must not return before the worker has
        }
        QVERIFY(context->isCancelled());
        const std::size_t atDelete = context->done;
        QTest::qWait(200);
        QCOMPARE(context->done.load(), atDelete); // the worker had ended: it counts no more
        QCOMPARE(*delivered, 0);                  // and nothing came late
    }

    void supersededJobIsCancelledAndDropped() {
        BackgroundJob job(nullptr, 20);
        std::vector<int> delivered;
        job.start<int>(countUntilCancelled, [&](int) { delivered.push_back(1); });
        const std::shared_ptr<JobContext> first = job.context();
        QTRY_VERIFY_WITH_TIMEOUT(first->done > 0, 10000);
        QSignalSpy ended(&job, &BackgroundJob::ended);
        job.start<int>([](JobContext&) { return 2; }, [&](int v) { delivered.push_back(v); });
        QVERIFY(first->isCancelled());
        QVERIFY(ended.wait(10000));
        QTest::qWait(200); // time for the first job's (dropped) finish to arrive
        QCOMPARE(delivered, std::vector<int>{2});
        QCOMPARE(ended.count(), 1);
    }

    void progressIsPolledNotSentPerUnit() {
        BackgroundJob job(nullptr, 20);
        QSignalSpy progress(&job, &BackgroundJob::progress);
        QSignalSpy ended(&job, &BackgroundJob::ended);
        job.start<int>(
            [](JobContext& c) {
                c.total = 200;
                for (int i = 0; i < 200; ++i) {
                    ++c.done;
                    std::this_thread::sleep_for(std::chrono::microseconds(500));
                }
                return 0;
            },
            [](int) {});
        QVERIFY(ended.wait(10000));
        QVERIFY(progress.count() >= 1);
        QVERIFY(progress.count() < 200); // polled every 20 ms over ~0.1-1 s, not per unit
        QCOMPARE(progress.last().at(0).toLongLong(), 200); // the final count before delivery
        QCOMPARE(progress.last().at(1).toLongLong(), 200);
    }

    void aThrowComesBackAsFailed() {
        BackgroundJob job;
        bool delivered = false;
        QSignalSpy failed(&job, &BackgroundJob::failed);
        job.start<int>([](JobContext&) -> int { throw std::runtime_error("grid.n_a = 0"); },
                       [&](int) { delivered = true; });
        QVERIFY(failed.wait(10000));
        QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("grid.n_a = 0"));
        QVERIFY(!delivered);
    }
};

QTEST_MAIN(TestBackgroundJob)
#include "tst_background_job.moc"
