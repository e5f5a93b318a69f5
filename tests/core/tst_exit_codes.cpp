// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli's exit codes (app/cli/ExitCode.h, compiled into this test): 2 for every kind of
// bad input, 3 for an output that could not be written, 4 for a model result that is not finite
// (it was 3, the code of a full disk, issue 31), 1 only for anything else - a bug.

#include "app/cli/Args.h"
#include "app/cli/ExitCode.h"
#include "core/base/InputError.h"
#include "core/base/InternalError.h"
#include "core/io/AtomicFile.h"
#include "core/io/StudyRowJson.h"
#include "core/records/Accelerogram.h"
#include "core/study/StudySpec.h"

#include <QtTest>

#include <new>

using namespace kinstab;

class TestExitCodes : public QObject {
    Q_OBJECT
private slots:
    void eachFailureHasItsCode() {
        QCOMPARE(cli::failureOf(cli::UsageError("--mu -1")).code, 2);
        QCOMPARE(cli::failureOf(InputError("building.stories")).code, 2);
        QCOMPARE(cli::failureOf(RecordError("a.AT2", 3, "not a number")).code, 2);
        QCOMPARE(cli::failureOf(StudyError("records: a.AT2")).code, 2);
        QCOMPARE(cli::failureOf(StudyRowError("r.jsonl:1: broken")).code, 2);
        QCOMPARE(cli::failureOf(FileError("p.json: cannot be read")).code, 2);
        QCOMPARE(cli::failureOf(WriteError("cannot write o: No space left")).code, 3);
        const cli::Failure nan = cli::failureOf(InternalError("tau_c = nan"));
        QCOMPARE(nan.code, 4);
        QCOMPARE(nan.prefix, std::string("no finite result: "));
        QCOMPARE(cli::failureOf(std::bad_alloc()).code, 1);
        QCOMPARE(cli::failureOf(std::logic_error("runStudyCase: the records were not read")).code,
                 1);
    }
};

QTEST_APPLESS_MAIN(TestExitCodes)
#include "tst_exit_codes.moc"
