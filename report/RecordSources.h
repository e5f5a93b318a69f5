// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The reference-list entry for an accelerogram: event, station, component, the database it
// comes from and the licence it is shipped under. The records shipped with kinstab are described
// in resources/records/SOURCES.md; a user's own file is cited by what its header says.

#include "core/records/Accelerogram.h"

#include <QString>

namespace kinstab::report {

// path: the file the project names (":/records/RSN77_SFERN_PUL164.AT2" or a file on disk).
QString recordCitation(const Accelerogram& record, const QString& path);

} // namespace kinstab::report
