// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A file's bytes read and written whole, for the cli tests that check what an output left behind.

#include <QByteArray>
#include <QFile>
#include <QString>
#include <QtTest>

// The file's bytes, or a marker that no output can equal when it cannot be read.
inline QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

inline void writeBytes(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}
