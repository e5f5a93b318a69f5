// SPDX-License-Identifier: GPL-3.0-or-later
// core/base/Sha256: the FIPS 180-4 examples, and Qt's SHA-256 over every length around the
// 64-byte block and its padding boundary, added whole and in uneven pieces.

#include "core/base/Sha256.h"

#include <QCryptographicHash>
#include <QRandomGenerator>
#include <QtTest>

using namespace kinstab;

class TestSha256 : public QObject {
    Q_OBJECT
private slots:
    void fipsExamples() {
        QCOMPARE(sha256Hex(""),
                 std::string("e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"));
        QCOMPARE(sha256Hex("abc"),
                 std::string("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"));
        QCOMPARE(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
                 std::string("248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1"));
        Sha256 million;
        const std::string thousand(1000, 'a');
        for (int i = 0; i < 1000; ++i)
            million.add(thousand);
        QCOMPARE(million.hex(),
                 std::string("cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"));
    }
    void equalsQtAtEveryLength() {
        QRandomGenerator random(31);
        for (int n = 0; n <= 300; ++n) {
            std::string bytes(static_cast<std::size_t>(n), '\0');
            for (char& c : bytes)
                c = static_cast<char>(random.bounded(256));
            const QByteArray qt =
                QCryptographicHash::hash(QByteArray(bytes.data(), n), QCryptographicHash::Sha256)
                    .toHex();
            QCOMPARE(QByteArray::fromStdString(sha256Hex(bytes)), qt);
            Sha256 pieces; // the same bytes added in pieces of 1 to 70 bytes
            for (std::size_t at = 0; at < bytes.size();) {
                const std::size_t take =
                    std::min<std::size_t>(bytes.size() - at, 1 + random.bounded(70));
                pieces.add(std::string_view(bytes).substr(at, take));
                at += take;
            }
            QCOMPARE(QByteArray::fromStdString(pieces.hex()), qt);
        }
    }
};

QTEST_APPLESS_MAIN(TestSha256)
#include "tst_sha256.moc"
