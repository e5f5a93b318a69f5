// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The GUI's saves and exports go through core's atomic writer (core/io/AtomicFile.h), as the
// CLI's do: the old file stays until the new one is complete, and a full disk is reported.

#include <QByteArray>
#include <QImage>
#include <QString>

namespace kinstab::ui {

// Writes the bytes to path; returns "" or the reason ("cannot write …: No space left on device").
QString saveAtomically(const QString& path, const QByteArray& bytes);
// Encodes the image (format "PNG", …) in memory, then saves it as above.
QString saveImageAtomically(const QString& path, const QImage& image, const char* format);

} // namespace kinstab::ui
