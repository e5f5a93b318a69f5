// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/VerticalRecord.h"

#include "core/base/InputError.h"
#include "core/records/RecordReader.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace kinstab {

namespace {
// The whole file, or an InputError with the system's reason (the words Qt's QFile gave before).
std::string fileText(const std::string& path, const std::string& field) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(field + std::strerror(errno != 0 ? errno : ENOENT));
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}
} // namespace

std::optional<Accelerogram> loadVerticalRecord(const PlanarSettings& s) {
    if (s.vertical == VerticalSource::None) return std::nullopt;
    const bool shipped = s.vertical == VerticalSource::Rsn68Up;
    const std::string path = shipped ? kRsn68UpSource : s.verticalPath;
    const std::string field = "planar.vertical = '" + path + "': ";
    const std::string text =
        shipped ? std::string(shippedRecordText(kRsn68UpFileName)) : fileText(path, field);
    try {
        return parseRecord(RecordText(text, path));
    } catch (const RecordError& e) {
        throw InputError(field + e.what());
    }
}

PlanarCase planarCaseWithVertical(const Slab1DCase& common, const PlanarSettings& s) {
    const std::optional<Accelerogram> record = loadVerticalRecord(s);
    return planarCaseFrom(common, s, record ? verticalMotion(*record, common.tstar) : nullptr);
}

} // namespace kinstab
