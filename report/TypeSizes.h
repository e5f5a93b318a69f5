// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The report's type sizes in points, one place for the pages' measuring (report/PageLayout.cpp)
// and their painting (report/PagePainting.cpp): a block is painted in the size it was measured in.

namespace kinstab::report {

inline constexpr double kBodyPt = 9.5;
inline constexpr double kSmallPt = 8.0;
inline constexpr double kTablePt = 8.5;
inline constexpr double kCaptionPt = 8.5;
inline constexpr double kTitlePt = 17.0;

inline double headingPt(int level) {
    return level <= 1 ? 13.0 : 10.5;
}

} // namespace kinstab::report
