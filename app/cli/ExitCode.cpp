// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/ExitCode.h"

#include "app/cli/Args.h"
#include "core/base/InputError.h"
#include "core/base/InternalError.h"
#include "core/io/AtomicFile.h"
#include "core/io/StudyRowJson.h"
#include "core/records/Accelerogram.h"
#include "core/study/StudySpec.h"

namespace kinstab::cli {

namespace {
template <class T> bool is(const std::exception& e) {
    return dynamic_cast<const T*>(&e) != nullptr;
}
} // namespace

Failure failureOf(const std::exception& e) {
    if (is<WriteError>(e)) return {3, "error: "}; // before FileError, of which it is one
    if (is<InternalError>(e)) return {4, "no finite result: "};
    // Input no command turned into a UsageError is bad input all the same: a record, study,
    // results or other file that cannot be read or is wrong.
    if (is<UsageError>(e) || is<InputError>(e) || is<RecordError>(e) || is<StudyError>(e) ||
        is<StudyRowError>(e) || is<FileError>(e))
        return {2, "error: "};
    return {1, "internal error (a bug in kinstab, please report it): "};
}

} // namespace kinstab::cli
