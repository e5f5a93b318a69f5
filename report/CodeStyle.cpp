// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/CodeStyle.h"

#include "core/codes/CodeCatalog.h"

namespace kinstab::report {

QString shortCodeName(const std::string& key) {
    const CodeInfo* c = findCode(key);
    return c ? QString::fromUtf8(c->shortName) : QString::fromStdString(key);
}

QColor codeColour(const std::string& key) {
    const CodeInfo* c = findCode(key);
    return c ? QColor::fromRgb(static_cast<QRgb>(c->rgb)) : QColor(Qt::gray);
}

} // namespace kinstab::report
