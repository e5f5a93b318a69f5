// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A table of contents for a long report: when the laid-out report has more than
// kContentsAfterPages pages, a page "Contents" listing each numbered section and its page goes
// where the builder marked it (after the front matter). Laid out twice: once with placeholder
// page numbers to find where every section lands, once with the numbers.

#include "report/PageLayout.h"
#include "report/ReportDocument.h"

#include <functional>
#include <memory>

namespace kinstab::report {

inline constexpr int kContentsAfterPages = 6;

// The document to print: `doc` itself, or a copy with the contents page. layoutOf lays a
// document out on the output device.
ReportDocument
withContents(const ReportDocument& doc,
             const std::function<std::unique_ptr<PageLayout>(const ReportDocument&)>& layoutOf);

} // namespace kinstab::report
