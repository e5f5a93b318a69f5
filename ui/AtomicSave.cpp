// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/AtomicSave.h"

#include "core/io/AtomicFile.h"

#include <QBuffer>

#include <string_view>

namespace kinstab::ui {

QString saveAtomically(const QString& path, const QByteArray& bytes) {
    try {
        writeFileAtomically(
            path.toStdString(),
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    } catch (const FileError& e) {
        return QString::fromUtf8(e.what());
    }
    return {};
}

QString saveImageAtomically(const QString& path, const QImage& image, const char* format) {
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, format))
        return QObject::tr("%1: cannot encode the image as %2")
            .arg(path, QString::fromLatin1(format));
    return saveAtomically(path, bytes);
}

} // namespace kinstab::ui
